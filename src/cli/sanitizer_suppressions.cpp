// Libraries that keep allocations for the life of the process, which LeakSanitizer
// (scripts/test.sh) would otherwise report as leaks of a test run or of the command line
// built with RIGDESIGN_SANITIZE (report and coverage draw with both):
// - Mesa's OSMesa (22.3, Debian 12) loses a few hundred bytes inside the library for every
//   context, even one created and destroyed at once;
// - fontconfig, which Cairo uses for text, caches its configuration until process exit.
// Only allocations made inside those libraries are suppressed. The sanitizer runtime reads
// this hook from the executable; without a sanitizer nothing calls it.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libfontconfig.so\n";
}
