# SPDX-License-Identifier: Apache-2.0
"""Fine position and velocity beside the core (issue 37): models of rtl/fine/.

    velocity        velocity and acceleration from the sync track's edge timing
                    (with its serial divider)
    tracker         the same from a tracking filter whose gains come from a table
                    (prenc_fine's TRACKER = 1)
    period          the velocity from the period of the sync track's last cycle, for a
                    small FPGA (prenc_fine's PERIOD = 1)
    tracker_gains   that table: the filter's gains by speed and age, for a disc and a
                    clock (`prenc gains`)
    fine_position   the fraction of the quarter passed, from the velocity, and the
                    position extrapolated to the instant a consumer asks
"""
