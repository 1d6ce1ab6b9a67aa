// tinygltf's and stb_image's implementations, compiled into the fuzz build with the sanitizers and coverage
// (the normal build links Debian's libtinygltf.so and libstb.a instead). Same headers, same defaults.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
