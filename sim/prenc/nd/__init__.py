# SPDX-License-Identifier: Apache-2.0
"""Error-tolerant codes: (n,d)-sequences and reading them by correlation.

From the second paper the project grew from (Wolfe & Chirikjian, "Error-Tolerant
Cyclic Sequences for Vision-Based Absolute Encoders"). A cyclic binary sequence of
length K is an (n,d)-sequence when any two of its K n-windows differ in at least d
bits. d = 1 is a de Bruijn-like code; with d >= 3 a reader can correct a bit error.

    sequence     windows, the independent minimum-distance check, text form
    algorithm1   the paper's Algorithm 1: breadth-first growth of paths (baseline)
    exact        depth-first search from one canonical rotation; proves maxima
    lfsr_codes   windows of m-sequences as linear codes: long sequences at once
    bounds       sound upper bounds on the length
    table        Table 1 of the paper, extended
    phasing      parallel sequences: the phasing of equation 1; the dual-track disc
    imaging      a camera looking at a cylinder that carries the sequences
    correlator   the integer correlation decoder (the model of rtl/nd/prenc_correlator.v)
"""
