// SHA-256 (FIPS 180-4) of bytes in memory, for the content hashes of the files a packed folder carries
// (DIR/input/manifest.json): strong enough that an edited art file is never taken for the packed one.
#pragma once

#include <string>
#include <string_view>

namespace animpak {

/// The digest as 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace animpak
