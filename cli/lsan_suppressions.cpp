// LeakSanitizer's built-in suppressions for sanitizer builds (GEARKIT_SANITIZE): CLN, under
// GiNaC, allocates tables in its static constructors and never frees them, by design. Compiled
// into the executable (whose kin --equations module loads them) and into every test program.
// print_suppressions=0: the statistics LeakSanitizer prints otherwise would break the stderr
// rule (one line per problem) that the tests check.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() { return "leak:libcln.so\nleak:libginac.so\n"; }
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif
