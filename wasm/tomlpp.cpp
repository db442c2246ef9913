// toml++'s implementation, compiled once for the WebAssembly module (wasm/CMakeLists.txt): the
// library is Debian's header package, whose implementation a program compiles in one file.
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
