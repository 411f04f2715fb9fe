"""Exact, test-side faults on one wire of the simulator: mutate chosen frames byte by byte.

``Tamper(sim, "usb_down", match, mutate, times=1)`` rewrites the next ``times`` complete
lines written on that wire for which ``match(line)`` is true, with ``mutate(line)``
(bytes; empty drops the frame). The wire's own fault injection still applies after.
"""

from __future__ import annotations

WIRES = ("usb_down", "usb_up", "uart_down", "uart_up")


def pieces(data: bytes) -> list[bytes]:
    parts = data.split(b"\n")
    out = [p + b"\n" for p in parts[:-1]]
    return out + ([parts[-1]] if parts[-1] else [])


class Tamper:
    def __init__(self, sim, wire: str, match, mutate, times: int = 1) -> None:
        self.faults = sim.wires[wire].faults
        self.original = self.faults.process
        self.match, self.mutate, self.times = match, mutate, times
        self.hits = 0
        self.faults.process = self.process

    def process(self, data: bytes):
        out = bytearray()
        for piece in pieces(data):
            if self.times and piece.endswith(b"\n") and self.match(piece):
                self.times -= 1
                self.hits += 1
                piece = self.mutate(piece)
            out += piece
        return self.original(bytes(out)) if out else []

    def remove(self) -> None:
        self.faults.process = self.original


def frame_of(kind: str, seq: int):
    """Match the frame ``<kind> <seq> ...`` (``D 5 ...``, ``A 5 16``, ``F 5``)."""
    head = f"{kind} {seq}".encode()
    return lambda line: line.startswith(head + b" ") or line.startswith(head + b"*")


def flip(position: int, bit: int = 0):
    """Flip bit ``bit`` (0-7) of the byte at ``position``, whatever byte that makes (a
    newline, ``!``, 0x18 ... : the wire spares nothing)."""

    def mutate(line: bytes) -> bytes:
        buf = bytearray(line)
        buf[position] ^= 1 << bit
        return bytes(buf)

    return mutate


def flip_into(value: int, index: int = 0):
    """Flip the one bit of the ``index``-th byte of a line that is a single bit away from
    ``value`` (e.g. a space into ``!``, ``8`` into 0x18, ``*`` into a newline)."""

    def mutate(line: bytes) -> bytes:
        near = [i for i, b in enumerate(line) if bin(b ^ value).count("1") == 1]
        position = near[index]
        return flip(position, (line[position] ^ value).bit_length() - 1)(line)

    return mutate


def drop_byte(position: int):
    return lambda line: line[:position] + line[position + 1 :]


def swap_adjacent_digits(line: bytes) -> bytes:
    """Swap the first two adjacent, different digits of the body."""
    body = line[: line.rindex(b"*")]
    for i in range(len(body) - 1):
        a, b = body[i : i + 1], body[i + 1 : i + 2]
        if a.isdigit() and b.isdigit() and a != b:
            return line[:i] + b + a + line[i + 2 :]
    raise AssertionError(f"no adjacent digits to swap in {line!r}")
