# SPDX-License-Identifier: Apache-2.0
"""Fine position and velocity beside the core: models of rtl/fine/ (docs/fine.md).

    velocity        the velocity from windows of the sync track's edges: the registers
                    around prenc_velocity's engine
    engine          that engine: an accumulator, a divider's and a multiplier's steps, a
                    register file in block RAM, run by a program
    program         the program (the estimator), and the RTL's ROM written from it
    fine_position   the fraction of the quarter passed, from the velocity, and the
                    position extrapolated to the instant a consumer asks
    fine            prenc_fine: both, and the calibration table between them and the disc
"""
