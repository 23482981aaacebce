# SPDX-License-Identifier: Apache-2.0
"""The virtual encoder: disc, heads and sync track, motion, faults, the scenarios and
campaigns that the tests and benchmarks run, and the plain reader they compare with.

    encoder       disc, heads, sync track, event stream
    trajectory    disc motion sampled on the reader's clock
    profiles      speed profiles
    faults        composable, seeded faults of the datasheet
    scenarios     named scenarios of the core's tests
    goals         the availability goals of issue 15, scenario by scenario
    campaign      long seeded fault campaigns
    plain_reader  the plain verifying reader (drop all on any disagreement)
    printing      a printed disc's imperfections (edges, phase, duty, eccentricity)
    fine_bench    the fine position and velocity against the truth, beside baselines
    edge_timing   a printed disc's true edges, and a steady run's crossings of them
    cal_bench     self-calibration against the truth
"""
