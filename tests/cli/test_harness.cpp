// The CLI tests' own harness (run_animpak.hpp): what it retries and what it does not.
#include <catch2/catch.hpp>

#include <string>

#include "run_animpak.hpp"
#include "temp_dir.hpp"

namespace {

// A shell command that appends a line to `count` on every run, so a test can read how often it ran.
std::string counted(const animpak::test::TempDir& dir, const std::string& body) {
  return "sh -c 'echo run >> " + (dir / "count").string() + "; " + body + "'";
}

int runs(const animpak::test::TempDir& dir) {
  const std::string text = read_text(dir / "count");
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace

TEST_CASE("CLI harness: a run ended by LeakSanitizer's tracer crash is run once more") {
  const animpak::test::TempDir dir("animpak-harness-");
  // The first run prints the crash LeakSanitizer prints and aborts; the second succeeds.
  const std::string crash_then_pass = "if [ -e " + (dir / "crashed").string() +
                                      " ]; then echo done; exit 0; fi; touch " + (dir / "crashed").string() +
                                      "; echo \"Tracer caught signal 11: addr=0x40b0\" >&2;"
                                      " echo \"==1==LeakSanitizer has encountered a fatal error.\" >&2; exit 134";
  const CommandResult r = run_command(counted(dir, crash_then_pass));
  CHECK(runs(dir) == 2);
  CHECK(r.code == 0);
  CHECK(r.out == "done\n");
}

TEST_CASE("CLI harness: a leak report, a failure or a second tracer crash is returned as it is") {
  SECTION("a leak LeakSanitizer reports") {
    const animpak::test::TempDir dir("animpak-harness-");
    const CommandResult r =
        run_command(counted(dir, "echo \"==1==ERROR: LeakSanitizer: detected memory leaks\" >&2; exit 1"));
    CHECK(runs(dir) == 1);
    CHECK(r.code == 1);
  }
  SECTION("an ordinary failure") {
    const animpak::test::TempDir dir("animpak-harness-");
    const CommandResult r = run_command(counted(dir, "echo broken >&2; exit 3"));
    CHECK(runs(dir) == 1);
    CHECK(r.code == 3);
    CHECK(r.err == "broken\n");
  }
  SECTION("the tracer crashing twice") {
    const animpak::test::TempDir dir("animpak-harness-");
    const CommandResult r = run_command(counted(
        dir,
        "echo \"Tracer caught signal 11\" >&2; echo \"LeakSanitizer has encountered a fatal error.\" >&2; exit 134"));
    CHECK(runs(dir) == 2);
    CHECK(r.code == 134);
  }
}
