# SPDX-License-Identifier: Apache-2.0
"""The bench's figures in docs/figures/ are up to date: drawn from the data kept beside
them (the same pictures, byte for byte), and that data measured on today's models (the
digest of the sources it comes from). After a change of a model, `scripts/bench.py
figures` (or a whole `make bench`) measures and draws them again."""

from __future__ import annotations

import pytest

from prenc.virtual import bench_figures as bf


def test_the_figures_data_was_measured_on_todays_models():
    data = bf.load()
    assert data["sources"] == bf.source_digest(), (
        "docs/figures/bench.json was measured on other sources than today's: run scripts/bench.py figures")


@pytest.mark.parametrize("name", sorted(bf.DRAWINGS))
def test_each_picture_is_drawn_from_the_data(name, tmp_path):
    bf.DRAWINGS[name](bf.load(), tmp_path / name)
    assert (tmp_path / name).read_bytes() == (bf.FIGURES / name).read_bytes(), (
        f"docs/figures/{name} is not what its data draws: run scripts/bench.py figures")


def test_the_pictures_show_every_scenario_and_estimator():
    data = bf.load()
    assert {"ideal", "printed", "calibrated"} <= set(data["accuracy"])
    assert set(bf.ESTIMATORS) <= set(data["accuracy"]["printed"])
    assert set(bf.ESTIMATORS) - {"ours, EDGE_TOLERANCE"} <= set(data["accuracy"]["ideal"])
    assert len(data["availability"]) >= 10 and all(r["core"] >= r["plain"] for r in data["availability"])
    assert len(data["calibration"]["runs"]) >= 5
