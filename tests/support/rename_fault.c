/* Fault injection for the output-folder tests, loaded with LD_PRELOAD into `saltus`:
 *   SALTUS_FAULT_KILL_AFTER_RENAME=N   SIGKILL the process right after its N-th rename
 *                                      (rename or renameat2) returns: a kill between renames;
 *   SALTUS_FAULT_NO_EXCHANGE=1         renameat2(RENAME_EXCHANGE) fails with EINVAL, as on file
 *                                      systems without it, so the two-rename fallback runs.
 * Test code only; nothing in Saltus knows about it. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static int g_renames = 0;

static void after_rename(void) {
  const char* limit = getenv("SALTUS_FAULT_KILL_AFTER_RENAME");
  ++g_renames;
  if (limit && atoi(limit) == g_renames) kill(getpid(), SIGKILL);
}

int rename(const char* from, const char* to) {
  int (*real)(const char*, const char*) =
      (int (*)(const char*, const char*))dlsym(RTLD_NEXT, "rename");
  const int result = real(from, to);
  const int saved = errno;
  if (result == 0) after_rename();
  errno = saved;
  return result;
}

int renameat2(int from_dir, const char* from, int to_dir, const char* to, unsigned int flags) {
  int (*real)(int, const char*, int, const char*, unsigned int) =
      (int (*)(int, const char*, int, const char*, unsigned int))dlsym(RTLD_NEXT, "renameat2");
  if ((flags & RENAME_EXCHANGE) && getenv("SALTUS_FAULT_NO_EXCHANGE")) {
    errno = EINVAL;
    return -1;
  }
  const int result = real(from_dir, from, to_dir, to, flags);
  const int saved = errno;
  if (result == 0) after_rename();
  errno = saved;
  return result;
}
