# SPDX-License-Identifier: Apache-2.0
"""prenc: reference model and tools for the pseudorandom absolute encoder reader.

Plain Python (numpy), no simulator imports: the cocotb testbenches in tb/ import
this package, never the other way round. One module per concept:

- lfsr       maximal-length LFSR sequences, primitive feedback sets
- debruijn   the disc code: de Bruijn completion, windows, next-bit laws
- rom        conversion ROM tables and track patterns in FPGA vendors' formats
- converter  model of rtl/core/prenc_converter.v, and the serial converter it replaces
- encoder    the virtual encoder: disc, heads, sync track, event stream
- trajectory disc motion sampled on the reader's clock
- faults     composable, seeded faults of the datasheet
"""

__version__ = "0.1.0"
