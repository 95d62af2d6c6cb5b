/* The floor of a JSON-lines round trip (docs/decider.md "Speed"): a parent writes a 400-byte line
 * to a child through one pipe and reads its 19-byte reply through another, STEPS times, both sides
 * blocking in read(), nothing computed on either side.
 *   cc -O2 bench/pipe_round_trip.c -o /tmp/pipe_round_trip && /tmp/pipe_round_trip [STEPS]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int main(int argc, char** argv) {
  const int steps = argc > 1 ? atoi(argv[1]) : 1607;
  int to_child[2], to_parent[2];
  if (pipe(to_child) != 0 || pipe(to_parent) != 0) return 1;
  char line[400], buffer[512];
  memset(line, 'x', sizeof line - 1);
  line[sizeof line - 1] = '\n';
  const pid_t child = fork();
  if (child == 0) {
    close(to_child[1]);
    while (read(to_child[0], buffer, sizeof buffer) > 0) {
      if (write(to_parent[1], "{\"blinker\":\"none\"}\n", 19) != 19) _exit(1);
    }
    _exit(0);
  }
  struct timespec start, end;
  clock_gettime(CLOCK_MONOTONIC, &start);
  for (int i = 0; i < steps; ++i) {
    if (write(to_child[1], line, sizeof line) != (ssize_t)sizeof line) return 1;
    if (read(to_parent[0], buffer, sizeof buffer) <= 0) return 1;
  }
  clock_gettime(CLOCK_MONOTONIC, &end);
  close(to_child[1]);
  waitpid(child, NULL, 0);
  const double seconds = (end.tv_sec - start.tv_sec) + (end.tv_nsec - start.tv_nsec) / 1e9;
  printf("%d round trips: %.1f ms, %.1f us each\n", steps, seconds * 1e3, seconds * 1e6 / steps);
  return 0;
}
