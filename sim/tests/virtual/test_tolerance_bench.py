# SPDX-License-Identifier: Apache-2.0
"""Section 14's tolerances at their extremes: never a wrong valid position, and the
calibration table takes the printing's error out of the fine position."""

from __future__ import annotations

import pytest

from prenc.virtual import tolerance_bench as tb
from prenc.virtual.printing import Printing


@pytest.mark.parametrize("printing", [Printing(phase_deg=30), Printing(duty_a=0.3, duty_b=0.3),
                                      Printing(eccentricity=0.3, eccentricity_phase=0.7)],
                         ids=["phase", "duty", "eccentricity"])
def test_the_core_never_reads_a_wrong_position_at_the_extremes(printing):
    valid, wrong = tb.core_row(printing)
    assert wrong == 0 and valid > 0.85


def test_the_table_takes_the_duty_error_out_of_the_fine_position():
    raw, calibrated = tb.fine_row(Printing(duty_a=0.35, duty_b=0.35))
    assert raw > 0.05 and calibrated < 1 / 256
