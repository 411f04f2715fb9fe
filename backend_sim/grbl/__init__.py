"""A GRBL 1.1 machine in software, written from GRBL's public interface, commands,
settings, alarms and errors documentation (no GRBL code): ``simulator.GrblSimulator``
behind ``sim://grbl`` and ``cnc-sim --grbl --pty``; motion from ``backend_sim.motion``.
Never imports ``app.gcode`` or ``app.ui``: it parses G-code with its own small parser.
"""
