// Compiled into every program that links vkref, in the sanitizer build only
// (SOFTRASTER_SANITIZE): dlclose does nothing, so the libraries the Vulkan loader opens (the
// driver, LLVM) stay mapped until the program exits. LeakSanitizer checks for leaks at exit and
// can name a library only while it is mapped; after a real dlclose the driver's frames read
// "<unknown module>" and no suppression in lsan.supp could match them by library name.
// Deliberately nothing else: the libraries still run their own clean-up; only the unmapping is
// skipped.
extern "C" int dlclose(void*) { return 0; }
