# SPDX-License-Identifier: Apache-2.0
"""The reader on a bus (rtl/bus/): the LiteX integration of prenc_wb (litex.py, which
needs LiteX; nothing else here does). The register map's Python access is generated
from rtl/bus/prenc_wb.rdl by scripts/regmap.py."""
