"""Issue 14 point 10: every fuzz target with a fixed example budget (derandomized, so a
run is repeatable); the long run is ``python -m bench bench_fuzz``."""

import pytest
from hypothesis import HealthCheck, given, settings

from tests.fuzz.targets import TARGETS

BUDGET = {"gcode text": 150, "gcode hostile": 60, "gcode bytes": 100, "deframer": 300, "codec": 300,
          "machine commands": 60, "dialect parser": 300, "settings loader": 150, "profile loader": 100}


@pytest.mark.parametrize("name", sorted(TARGETS))
def test_fuzz_target(name):
    strategy, target = TARGETS[name]
    run = settings(max_examples=BUDGET[name], deadline=None, derandomize=True, database=None,
                   suppress_health_check=list(HealthCheck))(given(strategy)(target))
    run()
