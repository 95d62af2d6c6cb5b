# Sourced by the shell tests that start a TraCI server on 127.0.0.1 (the caller defines $py, a Python
# 3, and `fail`):
#   free_port          a port nobody listens on now
#   wait_listening P   returns once a socket listens on port P, read from /proc/net/tcp (a probe
#                      connection would take one of the server's client places; a server that has
#                      not bound its port yet on a loaded machine would refuse it); `fail` after 10 s
free_port() { "$py" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
wait_listening() {
  local hex; hex=$(printf ':%04X ' "$1")
  for _ in $(seq 200); do
    awk '$4 == "0A" {print $2 " "}' /proc/net/tcp /proc/net/tcp6 2>/dev/null | grep -q "$hex" && return 0
    sleep 0.05
  done
  fail "no SUMO listening on port $1 after 10 s"
}
