"""Issue 14 point 2: jobs complete through per-byte noise on both hops, both directions.

Three seeds at 3e-3 per byte (drop, corrupt, duplicate, noise in equal shares on all
four wires), homing and a 1,000-line job each: every run completes, the executed log
is exactly the program, and the host never calls the link lost. The full matrix
(20 seeds, 1e-4..1e-2, lines/s, resends) is ``python -m bench bench_noisy``.
"""

import pytest

from tests.comm.noisy import noisy_run
from tests.comm.simlink import dialect_program

LINES = dialect_program(1000, seed=5)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_job_completes_exactly_at_3e_3(tmp_path, seed):
    outcome = noisy_run(LINES, 3e-3, seed, tmp_path)
    assert outcome.completed, outcome
    assert outcome.exact, outcome
    assert outcome.false_losses == 0, outcome
    assert outcome.resends > 0, "the faults never fired"


def test_job_completes_exactly_at_1e_2(tmp_path):
    outcome = noisy_run(LINES[:300], 1e-2, 7, tmp_path)
    assert outcome.completed and outcome.exact and outcome.false_losses == 0, outcome
