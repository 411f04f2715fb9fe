"""``cnc-sim`` / ``python -m backend_sim``: the simulated machine behind a pty or a socket.

``--pty`` prints exactly one line ``PTY /dev/pts/N`` on stdout, then serves until
SIGINT/SIGTERM; ``--tcp PORT`` prints ``TCP 127.0.0.1:PORT`` and serves
``socket://127.0.0.1:PORT``. ``--speed`` sets the clock's speed factor (1 = real time).
Fault flags set seeded per-byte error rates on the chosen hop(s) and direction(s).
``--grbl`` serves the simulated GRBL 1.1 machine (``backend_sim.grbl``) instead.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading

from app.profile import read_profile


def _positive(text: str) -> float:
    value = float(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"{text}: must be > 0")
    return value


def _rate(text: str) -> float:
    value = float(text)
    if not 0.0 <= value <= 1.0:
        raise argparse.ArgumentTypeError(f"{text}: a probability 0..1")
    return value


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="cnc-sim", description="The simulated CNC mill (both MCUs).")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--pty", action="store_true", help="serve on a pseudo-terminal")
    where.add_argument("--tcp", type=int, metavar="PORT", help="serve on 127.0.0.1:PORT")
    p.add_argument("--speed", type=_positive, default=1.0, help="speed factor of the clock (default 1)")
    p.add_argument("--sd", metavar="DIR", help="folder standing for the SD card")
    p.add_argument("--profile", metavar="FILE", help="machine profile (TOML or JSON)")
    p.add_argument("--exec-log", metavar="FILE", help="append seq<TAB>line of every executed line")
    p.add_argument("--mode", choices=("planner", "simple"), default="planner")
    p.add_argument("--grbl", action="store_true", help="a GRBL 1.1 machine instead (backend_sim.grbl)")
    p.add_argument("--seed", type=int, default=None, help="seed of boot ids and random faults")
    what = {"drop": "a byte dropped", "corrupt": "one bit of a byte flipped (whatever byte that makes)",
            "duplicate": "a byte sent twice", "noise": "a burst of 1-16 random bytes 0x00-0xFF after a byte"}
    for kind in ("drop", "corrupt", "duplicate", "noise"):
        p.add_argument(f"--{kind}-rate", type=_rate, default=0.0, metavar="P",
                       help=f"per-byte probability of {what[kind]}")
    p.add_argument("--fault-hop", choices=("usb", "uart", "both"), default="usb")
    p.add_argument("--fault-direction", choices=("down", "up", "both"), default="both")
    return p


def _apply_faults(sim, args) -> None:
    rates = {k: getattr(args, f"{k}_rate") for k in ("drop", "corrupt", "duplicate", "noise")}
    if not any(rates.values()):
        return
    hop = None if args.fault_hop == "both" else args.fault_hop
    direction = None if args.fault_direction == "both" else args.fault_direction
    sim.faults.set_rates(hop, direction, seed=args.seed or 0, **rates)


def load_profile_for_sim(path: str):
    """The profile of ``path``; each bad value is named on stderr and its default used
    (a bad profile never keeps the simulator from starting)."""
    read = read_profile(path)
    for problem in read.problems:
        print(f"cnc-sim: {problem}", file=sys.stderr)
    return read.profile


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    profile = load_profile_for_sim(args.profile) if args.profile else None
    from backend_sim.serve import PtyServer, TcpServer
    from backend_sim.simulator import Simulator

    if args.grbl:
        from backend_sim.grbl.simulator import GrblSimulator

        sim = GrblSimulator(profile, seed=args.seed)
    else:
        sim = Simulator(profile, sd_dir=args.sd, mode=args.mode, seed=args.seed, exec_log=args.exec_log)
        _apply_faults(sim, args)
    server = PtyServer(sim) if args.pty else TcpServer(sim, args.tcp)
    where = f"PTY {server.path}" if args.pty else f"TCP 127.0.0.1:{server.address[1]}"
    stop = threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.set())
    sim.start(args.speed)
    server.start()
    print(where, flush=True)
    while not stop.wait(0.5):
        pass
    server.close()
    sim.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
