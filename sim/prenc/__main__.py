# SPDX-License-Identifier: Apache-2.0
"""`python -m prenc ...` runs the `prenc` command (prenc.cli.main)."""

import sys

from .cli.main import main

sys.exit(main())
