"""Real-time factor of the whole simulator (both MCUs, the UART, three axes and the
spindle at 1 kHz) running the largest sample of resources/samples as fast as possible.

The program is normalised by ``app.gcode`` (the bench may import it; backend_sim never
does), written to the simulated SD card and run with ``SD RUN``, so the main MCU
streams it over the modelled UART to the CNC MCU. Prints the figure; target >= 100x.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

from app.comm.frame import seal
from backend_sim.simulator import Simulator

SAMPLES = Path(__file__).resolve().parent.parent / "resources" / "samples"


def largest_sample() -> Path:
    files = [p for p in SAMPLES.glob("*") if p.suffix.lower() in (".ngc", ".nc", ".gcode", ".tap")]
    return max(files, key=lambda p: p.stat().st_size)


def device_lines(path: Path) -> list[str]:
    from app.gcode import load

    return list(load(path).device_lines)


def run_job(lines: list[str], mode: str = "planner") -> dict[str, float]:
    with tempfile.TemporaryDirectory() as sd:
        (Path(sd) / "job.nc").write_text("\n".join(lines) + "\n", encoding="ascii")
        sim = Simulator(sd_dir=sd, seed=1, mode=mode)
        sim.host_port.write(seal("C 1 HOME"))
        homed_at = _timed(sim, lambda: sim.cnc.mc.homed and sim.cnc.mc.state == "IDLE", 300)
        sim.host_port.write(seal("C 2 SD RUN job.nc"))
        sim.run_for(0.05)
        job = _timed(sim, lambda: sim.main.sd_job is None and sim.cnc.mc.idle(), 36000)
        return {"lines": len(lines), "executed": len(sim.exec_log),
                "homing_sim": homed_at[0], "homing_wall": homed_at[1], "homing_cpu": homed_at[2],
                "job_sim": job[0], "job_wall": job[1], "job_cpu": job[2]}


def _timed(sim: Simulator, predicate, timeout: float) -> tuple[float, float, float]:
    """(simulated s, wall s, CPU s of this process) taken until ``predicate()``."""
    t_sim, t_wall, t_cpu = sim.clock.now, time.perf_counter(), time.process_time()
    if not sim.run_until(predicate, timeout):
        raise RuntimeError(f"not done after {timeout} simulated s")
    return sim.clock.now - t_sim, time.perf_counter() - t_wall, time.process_time() - t_cpu


def main() -> None:
    path = largest_sample()
    lines = device_lines(path)
    r = run_job(lines)
    print(f"sample: {path.name}, {r['lines']} device lines, {r['executed']} executed")
    for part in ("homing", "job"):
        sim_s, wall, cpu = r[f"{part}_sim"], r[f"{part}_wall"], r[f"{part}_cpu"]
        print(f"{part:7s} {sim_s:6.1f} s simulated in {wall:5.2f} s wall ({sim_s / wall:4.0f}x), "
              f"{cpu:5.2f} s CPU ({sim_s / cpu:4.0f}x)")
    sim_s = r["homing_sim"] + r["job_sim"]
    wall, cpu = r["homing_wall"] + r["job_wall"], r["homing_cpu"] + r["job_cpu"]
    print(f"real-time factor (target >= 100x): {sim_s / wall:.0f}x wall clock, "
          f"{sim_s / cpu:.0f}x per CPU second (the wall figure drops when the cores are shared)")


if __name__ == "__main__":
    main()
