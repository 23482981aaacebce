# SPDX-License-Identifier: Apache-2.0
"""Fine position and velocity beside the core (issue 37): models of rtl/fine/.

    velocity        velocity and acceleration from the sync track's edge timing
                    (with its serial divider)
    fine_position   the fraction of the quarter passed, from the velocity, and the
                    position extrapolated to the instant a consumer asks
"""
