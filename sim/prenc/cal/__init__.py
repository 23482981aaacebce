# SPDX-License-Identifier: Apache-2.0
"""Self-calibration of the sync track (issue 38): the disc measures its own edges.

    table            the calibration table: 4 x 2^N corrections, its file format and checks
    calibrate        from the edge timing of a few steady turns to the table, with the
                     checks that the run was fit for it
    lookup           model of rtl/cal/prenc_cal_lookup.v: the table in block RAM, a
                     quarter's two corrections
    edge_capture     model of rtl/cal/prenc_edge_capture.v: the edges' timing for a run
"""
