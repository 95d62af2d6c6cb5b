#!/usr/bin/env python3
"""A TCP server on 127.0.0.1 that is not SUMO, for the --connect tests (traci_peer_test.sh,
cli_bad_input.sh): it binds a free port, writes the port to PORT_FILE, takes one connection
(then creates PORT_FILE.connected) and behaves as MODE:

  zeros    sends four zero bytes at once (a length prefix SUMO 1.15's socket code asserts on)
  ones     sends ff ff ff ff (a negative length)
  random   sends 64 bytes of a fixed pseudo-random sequence
  huge     sends the length prefix 7f ff ff f0 (2 GiB) and nothing more
  silent   reads what comes and never answers (a server that accepts but does not speak TraCI)

It keeps the connection open until the client closes it, then ends; the test stops it by its PID
otherwise. Standard library only.

usage: traci_peer.py MODE PORT_FILE
"""
import os
import random
import socket
import sys

PAYLOADS = {
    "zeros": b"\x00\x00\x00\x00",
    "ones": b"\xff\xff\xff\xff",
    "random": bytes(random.Random(7).randrange(256) for _ in range(64)),
    "huge": b"\x7f\xff\xff\xf0",
    "silent": b"",
}


def main():
    mode, port_file = sys.argv[1], sys.argv[2]
    payload = PAYLOADS[mode]
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(1)
    with open(port_file + ".tmp", "w") as out:
        out.write(str(server.getsockname()[1]))
    os.replace(port_file + ".tmp", port_file)  # the test sees the whole number or nothing
    connection, _ = server.accept()
    open(port_file + ".connected", "w").close()  # the test may signal the client from now on
    if payload:
        connection.sendall(payload)
    try:
        while connection.recv(65536):  # until the client closes the connection
            pass
    except OSError:  # or resets it
        pass


if __name__ == "__main__":
    main()
