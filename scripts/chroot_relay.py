#!/usr/bin/env python3
"""The chroot suites' way to the Debian archive from a network namespace of their own (the
harness's, never the README's steps). A chroot's build and tests need their own namespace (X
displays are abstract sockets, shared by everything in one namespace), but the README's
commands install packages too: apt in the chroot uses http://127.0.0.1:PORT as its proxy, this
relay carries each connection through a Unix socket (a file: it crosses namespaces) to a second
relay on the host, which connects to the archive's host. Bytes are carried unchanged: apt asks
a proxy with the absolute URL, which the archive's server answers.

  chroot_relay.py host SOCKET HOST PORT   on the host: SOCKET -> HOST:PORT
  chroot_relay.py inner PORT SOCKET READY in the namespace: brings lo up, 127.0.0.1:PORT -> SOCKET
                                          (READY is created once it listens)
Each runs until killed."""
import fcntl
import os
import socket
import struct
import sys
import threading


def loopback_up():
    """A new network namespace starts with lo down: `ip link set lo up`, without iproute2."""
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    SIOCGIFFLAGS, SIOCSIFFLAGS, IFF_UP = 0x8913, 0x8914, 0x1
    flags = struct.unpack("16sH", fcntl.ioctl(s, SIOCGIFFLAGS, struct.pack("16sH", b"lo", 0)))[1]
    fcntl.ioctl(s, SIOCSIFFLAGS, struct.pack("16sH", b"lo", flags | IFF_UP))
    s.close()


def pump(src, dst):
    try:
        while True:
            data = src.recv(65536)
            if not data:
                break
            dst.sendall(data)
    except OSError:
        pass
    finally:
        for s in (src, dst):
            try:
                s.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass


def serve(listener, connect):
    while True:
        client, _ = listener.accept()
        try:
            upstream = connect()
        except OSError as e:
            print(f"chroot_relay: cannot connect: {e}", file=sys.stderr)
            client.close()
            continue
        for a, b in ((client, upstream), (upstream, client)):
            threading.Thread(target=pump, args=(a, b), daemon=True).start()


def main():
    mode = sys.argv[1] if len(sys.argv) > 1 else ""
    if mode == "host" and len(sys.argv) == 5:
        path, host, port = sys.argv[2], sys.argv[3], int(sys.argv[4])
        if os.path.exists(path):
            os.unlink(path)
        listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        listener.bind(path)
        listener.listen(64)

        def connect():
            s = socket.create_connection((host, port), timeout=60)
            s.settimeout(None)  # apt may keep a connection idle while it unpacks
            return s
        serve(listener, connect)
    elif mode == "inner" and len(sys.argv) == 5:
        port, path, ready = int(sys.argv[2]), sys.argv[3], sys.argv[4]
        loopback_up()
        listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        listener.bind(("127.0.0.1", port))
        listener.listen(64)
        open(ready, "w").close()

        def connect():
            s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            s.connect(path)
            return s
        serve(listener, connect)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
