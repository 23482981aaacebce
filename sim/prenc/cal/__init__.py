# SPDX-License-Identifier: Apache-2.0
"""Self-calibration of the sync track (issue 38): the disc measures its own edges.

    table      the calibration table: 4 x 2^N corrections, its file format and checks
    calibrate  from the edge timing of a few steady turns to the table, with the checks
               that the run was fit for it
"""
