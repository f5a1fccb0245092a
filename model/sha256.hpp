#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 hex digits: the scene hash in every provenance
// header. Written here to avoid a crypto library dependency for one checksum.
#include <string>
#include <string_view>

namespace granmix::model {

std::string sha256_hex(std::string_view data);

}  // namespace granmix::model
