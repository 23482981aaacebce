# SPDX-License-Identifier: Apache-2.0
"""The disc's code and its tables: LFSR sequences, the de Bruijn code, conversion ROMs
and track patterns.

    lfsr        maximal-length LFSR sequences, primitive feedback sets
    debruijn    the disc code: de Bruijn completion, windows, next-bit laws
    rom         conversion ROM tables and track patterns in FPGA vendors' formats
"""
