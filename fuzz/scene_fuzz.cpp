// libFuzzer target: the scene entry point (fuzz/entry.h). Run it with scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    collide::fuzz::scene(std::string(reinterpret_cast<const char*>(data), size));
    return 0;
}
