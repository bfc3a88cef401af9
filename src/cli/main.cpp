#include "commands.hpp"

int main(int argc, char** argv) { return animpak::cli::run(argc, argv); }
