// The fuzz build compiles tinyobjloader's parser from its header (float, as the system's
// libtinyobjloader that the default build links), so libFuzzer sees its branches.
// Deliberately nothing else.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
