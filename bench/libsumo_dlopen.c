/* How long loading Debian's libsumo takes by itself (docs/decider.md "Speed"): dlopen of
 * libsumocpp.so and the shared libraries it needs, in a fresh process, nothing else.
 *   cc -O2 bench/libsumo_dlopen.c -o /tmp/libsumo_dlopen && /tmp/libsumo_dlopen
 *   LD_DEBUG=statistics /tmp/libsumo_dlopen      # the dynamic loader's relocation count
 */
#include <dlfcn.h>
#include <stdio.h>
#include <time.h>

int main(void) {
  struct timespec start, end;
  clock_gettime(CLOCK_MONOTONIC, &start);
  void* handle = dlopen("libsumocpp.so", RTLD_LAZY | RTLD_LOCAL);
  clock_gettime(CLOCK_MONOTONIC, &end);
  if (!handle) {
    fprintf(stderr, "libsumo_dlopen: %s\n", dlerror());
    return 1;
  }
  printf("dlopen libsumocpp.so: %.1f ms\n",
         (end.tv_sec - start.tv_sec) * 1e3 + (end.tv_nsec - start.tv_nsec) / 1e6);
  return 0;
}
