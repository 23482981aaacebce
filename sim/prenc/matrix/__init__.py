# SPDX-License-Identifier: Apache-2.0
"""2-D matrix codes: n tracks on which every n x n window appears exactly once.

From the third paper the project grew from (Dziwinski, "A Novel Approach of an
Absolute Encoder Coding Pattern"). A column of the n tracks is one symbol of an
alphabet of 2^n, so a matrix code is a de Bruijn sequence of order n over 2^n
symbols: 2^(n*n) positions, read by a small image sensor.

    code      the code: FKM (Lyndon-word) generation, columns, windows, bit order,
              the checksum variant (one even-parity track)
    graph     the paper's graph G (Definition 3): Hamiltonian-cycle search and count,
              the closed formula for the number of de Bruijn sequences
    paper     the paper's 16-position example, checked; Table I of angles
    rom       conversion ROMs in the formats of `prenc rom`
    sensor    an image sensor looking at the tracks: blur, noise, sub-cell offsets
    reader    the integer model of rtl/matrix/prenc_matrix_reader.v
"""
