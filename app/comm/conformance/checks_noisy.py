"""A noisy wire: the kit corrupts its own bytes while it streams a job (check mode).

Every byte it writes may be flipped in one bit (becoming any of the 256 values, `\\n`
included), dropped or doubled, and bursts of random bytes (0x00-0xFF, 1-20 long) come
between and inside frames. The document's promises: a bad frame is dropped and
answered, nothing a corruption makes is ever carried out, and the job ends with every
line once (`F` of the last line, no refusal, no hold, stop or alarm). The seed is in
the note, so a failing run can be repeated.
"""

from __future__ import annotations

import random

from app.comm.conformance.kit import Kit
from app.comm.conformance.stream import Streamer

NOISY = "Errors and resends"
RATE = 3e-3  # per byte, for each of flip, drop, double
BURST_RATE = 0.02  # per write
LINES = 200


class Noise:
    """The kit's write filter: seeded flips, drops, doubles and bursts."""

    def __init__(self, seed: int, rate: float = RATE, burst_rate: float = BURST_RATE) -> None:
        self.rng, self.rate, self.burst_rate = random.Random(seed), rate, burst_rate
        self.counts = {"flip": 0, "drop": 0, "double": 0, "burst": 0}

    def __call__(self, data: bytes) -> bytes:
        rng, out = self.rng, bytearray()
        if rng.random() < self.burst_rate:
            out += self._burst()
        for byte in data:
            if rng.random() < self.rate:
                self.counts["drop"] += 1
                continue
            if rng.random() < self.rate:
                self.counts["flip"] += 1
                byte ^= 1 << rng.randrange(8)
            out.append(byte)
            if rng.random() < self.rate:
                self.counts["double"] += 1
                out.append(byte)
            if rng.random() < self.burst_rate / max(len(data), 1):
                out += self._burst()
        return bytes(out)

    def _burst(self) -> bytes:
        self.counts["burst"] += 1
        return bytes(self.rng.randrange(256) for _ in range(self.rng.randint(1, 20)))


def noisy_job(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(True)
    status = link.status()
    link.command(f"JOB {LINES}")
    seed = random.randrange(1 << 30)
    noise = Noise(seed)
    lines = [f"G01 X{k % 60 + 1}.5 Y{k % 40 + 1} F{800 + k % 7}" for k in range(LINES)]
    start = len(link.replies)
    link.corrupt = noise
    try:
        out = Streamer(link, lines, int(status.free) if status else 1).run(120.0)
    finally:
        link.corrupt = None
    replies = link.since(start)
    trouble = [
        r for r in replies if r.kind in "EX" or (r.kind == "S" and r.status().state in ("HOLD", "ALARM"))
    ]
    note = f"seed {seed}, injected {noise.counts}, {out.resends} resends, {len(out.naks)} N"
    kit.check(
        "noisy.job-completes",
        NOISY,
        "with the host's own bytes corrupted (flips to any byte value, drops, "
        "doubles, random bursts) the job ends with `F` of its last line",
        out.complete,
        f"JOB {LINES}, D 0..{LINES - 1} through a noisy filter",
        f"F {out.done}, A {out.acked}",
        note,
    )
    kit.check(
        "noisy.nothing-forged",
        NOISY,
        "no corruption is ever carried out: no refusal, no alarm, no hold or stop the host did not ask for",
        not trouble,
        f"JOB {LINES} through noise",
        " | ".join(str(r) for r in trouble[:4]) or "none",
        note,
    )
    _, alive = link.command("GET OPTSTOP")
    kit.check(
        "noisy.answers-afterwards",
        NOISY,
        "after the noise the machine answers as before",
        alive is not None,
        "C <id> GET OPTSTOP",
        str(alive),
    )
    kit.ensure_idle()
    kit.check_mode(False)


GARBAGE_BYTES = 20_000


def garbage_at_rest(kit: Kit) -> None:
    """Random bytes (all 256 values, bursts of 1-200) at a machine at rest start nothing."""
    link = kit.link
    kit.ensure_idle()
    link.idle(0.6)  # statuses still on their way (an `S` names no command) are read first
    before = kit.status_until(lambda st: True)
    rng, sent = random.Random(), 0
    seed = rng.randrange(1 << 30)
    rng.seed(seed)
    start, first_id = len(link.replies), link.next_id
    while sent < GARBAGE_BYTES:
        burst = bytes(rng.randrange(256) for _ in range(rng.randint(1, 200)))
        link.write(burst)
        sent += len(burst)
        link.pump()
    link.write(b"\n")
    link.idle(0.6)
    after = kit.status_until(lambda st: True)
    ours = range(first_id, link.next_id)
    forged = [
        r
        for r in link.since(start)
        if r.kind in "OE" and r.id is not None and r.id not in ours or r.kind == "X" or r.kind in "AF"
    ]
    moved = (
        before is None
        or after is None
        or (before.state, before.x, before.y, before.z, before.acc)
        != (after.state, after.x, after.y, after.z, after.acc)
    )
    kit.check(
        "noisy.garbage-starts-nothing",
        NOISY,
        "no corruption can hold, stop or start anything: random bytes "
        "at a machine at rest are bad frames, nothing is carried out, the machine answers after",
        not forged and not moved and after is not None,
        f"{sent} random bytes in bursts of 1-200",
        f"before {before}; after {after}; " + (" | ".join(str(r) for r in forged[:3]) or "nothing forged"),
        f"seed {seed}",
    )


CHECKS = [garbage_at_rest, noisy_job]
