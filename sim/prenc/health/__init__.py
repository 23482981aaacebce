# SPDX-License-Identifier: Apache-2.0
"""The warning before a failure (rtl/health/): how often the reader corrects its heads.

    health    prenc_health: a leaky bucket of corrections per source, and the warning
"""
