"""Fault injection on the links: what one direction of one hop does to the bytes.

``ChannelFaults.process(data)`` turns the bytes a sender writes into what the wire
carries: a list of ``(delay_s, bytes)`` pieces. Two kinds of faults:

- one-shot frame faults, armed with ``arm(kind, frames=1, **params)`` and applied to
  the next complete line (a piece ending in ``\\n``) written: ``drop``, ``corrupt``
  (one bit of one byte flipped, the newline included), ``duplicate``, ``delay``
  (``seconds``; the frames behind it are not held up, so they overtake it),
  ``reorder`` (held back until the next line has gone), ``noise`` (``nbytes`` random
  bytes 0x00-0xFF and a newline before it), ``truncate`` (only the first ``keep``
  bytes, no newline);
- seeded random per-byte rates (``set_rates``: drop, corrupt, duplicate, noise), for
  soak tests and benchmarks: the same seed and traffic give the same faults.

The model is honest (issue 18): a flip is any of the 8 bits of any byte, so it makes
whatever byte it makes (a newline, ``!``, 0x18, any of 256); drops and duplicates hit
any byte; a noise event inserts a burst of 1 to ``NOISE_BURST`` random bytes 0x00-0xFF
after any byte, between frames or inside them. Nothing is spared: not newlines, not
the CRC, not real-time frames.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from dataclasses import dataclass, field

FRAME_FAULTS = ("drop", "corrupt", "duplicate", "delay", "reorder", "noise", "truncate")
RATE_FAULTS = ("drop", "corrupt", "duplicate", "noise")
NOISE_BURST = 16
"""Longest burst of random bytes one noise event of ``set_rates`` inserts."""


@dataclass
class Armed:
    kind: str
    frames: int
    params: dict


@dataclass
class ChannelFaults:
    """The faults of one direction of one hop (e.g. ``usb_down``)."""

    name: str
    seed: int = 0
    armed: list[Armed] = field(default_factory=list)
    rates: dict[str, float] = field(default_factory=dict)
    counts: Counter = field(default_factory=Counter)
    _rng: random.Random = field(default_factory=random.Random, repr=False)
    _skip: dict[str, int] = field(default_factory=dict, repr=False)
    _held: bytes | None = None

    def __post_init__(self) -> None:
        self._rng.seed(f"{self.name}:{self.seed}")

    # ------------------------------------------------------------------ setup

    def arm(self, kind: str, frames: int = 1, **params) -> None:
        if kind not in FRAME_FAULTS:
            raise ValueError(f"unknown fault {kind!r}; known: {', '.join(FRAME_FAULTS)}")
        self.armed.append(Armed(kind, frames, params))

    def set_rates(self, seed: int | None = None, **rates: float) -> None:
        """Per-byte probabilities, e.g. ``set_rates(drop=1e-3, corrupt=1e-3, seed=7)``."""
        bad = set(rates) - set(RATE_FAULTS)
        if bad:
            raise ValueError(f"unknown rate {sorted(bad)}; known: {', '.join(RATE_FAULTS)}")
        if seed is not None:
            self.seed = seed
            self._rng.seed(f"{self.name}:{seed}")
        self.rates = {k: v for k, v in rates.items() if v > 0}
        self._skip = {k: self._gap(v) for k, v in self.rates.items()}

    def clear(self) -> None:
        self.armed.clear()
        self.rates.clear()
        self._skip.clear()

    @property
    def active(self) -> bool:
        return bool(self.armed or self.rates or self._held)

    # ------------------------------------------------------------------ applying

    def process(self, data: bytes) -> list[tuple[float, bytes]]:
        if not self.active:
            return [(0.0, data)]
        out: list[tuple[float, bytes]] = []
        for piece in _pieces(data):
            if piece.endswith(b"\n"):
                out.extend(self._line(piece))
            else:
                out.append((0.0, piece))
        if self.rates:
            out = [(d, self._random(p)) for d, p in out]
        return [(d, p) for d, p in out if p]

    def _line(self, line: bytes) -> list[tuple[float, bytes]]:
        held, self._held = self._held, None
        out: list[tuple[float, bytes]] = [(0.0, line)]
        if self.armed:
            fault = self.armed[0]
            fault.frames -= 1
            if fault.frames <= 0:
                self.armed.pop(0)
            self.counts[fault.kind] += 1
            out = _FRAME_HANDLERS[fault.kind](self, line, fault.params)
        if held is not None:
            out.append((0.0, held))
        return out

    # frame faults: each returns the pieces that go on the wire instead of ``line``

    def _drop(self, line: bytes, params: dict) -> list:
        return []

    def _corrupt(self, line: bytes, params: dict) -> list:
        return [(0.0, self._flip(line, self._rng.randrange(len(line))))]

    def _duplicate(self, line: bytes, params: dict) -> list:
        return [(0.0, line), (0.0, line)]

    def _delay(self, line: bytes, params: dict) -> list:
        return [(float(params.get("seconds", 0.2)), line)]

    def _reorder(self, line: bytes, params: dict) -> list:
        self._held = line
        return []

    def _noise(self, line: bytes, params: dict) -> list:
        junk = self._random_bytes(int(params.get("nbytes", 8)))
        return [(0.0, junk + b"\n" + line)]

    def _truncate(self, line: bytes, params: dict) -> list:
        keep = params.get("keep")
        keep = len(line) // 2 if keep is None else int(keep)
        return [(0.0, line[: min(keep, len(line) - 1)])]

    # random per-byte faults

    def _gap(self, rate: float) -> int:
        """Bytes until the next event of a Bernoulli(rate) process (geometric)."""
        if rate >= 1:
            return 0
        return int(math.log(1.0 - self._rng.random()) / math.log(1.0 - rate))

    def _random(self, data: bytes) -> bytes:
        buf = bytearray(data)
        for kind in RATE_FAULTS:
            if kind in self.rates:
                buf = self._apply_rate(kind, buf)
        return bytes(buf)

    def _apply_rate(self, kind: str, buf: bytearray) -> bytearray:
        out, pos = bytearray(), 0
        while self._skip[kind] < len(buf) - pos:
            i = pos + self._skip[kind]
            out += buf[pos:i]
            out += self._byte_fault(kind, buf[i])
            self.counts[f"rate_{kind}"] += 1
            pos = i + 1
            self._skip[kind] = self._gap(self.rates[kind])
        self._skip[kind] -= len(buf) - pos
        out += buf[pos:]
        return out

    def _byte_fault(self, kind: str, byte: int) -> bytes:
        if kind == "drop":
            return b""
        if kind == "duplicate":
            return bytes((byte, byte))
        if kind == "noise":
            return bytes((byte,)) + self._random_bytes(self._rng.randint(1, NOISE_BURST))
        return self._flip(bytes((byte,)), 0)

    def _random_bytes(self, count: int) -> bytes:
        """``count`` bytes drawn from all 256 values."""
        return self._rng.randbytes(count)

    def _flip(self, data: bytes, index: int) -> bytes:
        """Flip one of the 8 bits of byte ``index``: whatever byte that makes."""
        buf = bytearray(data)
        buf[index] ^= 1 << self._rng.randrange(8)
        return bytes(buf)


_FRAME_HANDLERS = {
    "drop": ChannelFaults._drop,
    "corrupt": ChannelFaults._corrupt,
    "duplicate": ChannelFaults._duplicate,
    "delay": ChannelFaults._delay,
    "reorder": ChannelFaults._reorder,
    "noise": ChannelFaults._noise,
    "truncate": ChannelFaults._truncate,
}


def _pieces(data: bytes) -> list[bytes]:
    """Split after every newline, keeping it: ``b"a\\nb"`` -> ``[b"a\\n", b"b"]``."""
    parts = data.split(b"\n")
    pieces = [p + b"\n" for p in parts[:-1]]
    if parts[-1]:
        pieces.append(parts[-1])
    return pieces
