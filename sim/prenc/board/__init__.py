# SPDX-License-Identifier: Apache-2.0
"""Models of the board's outputs and link (rtl/board/) and the host side of the link.

    turns     prenc_turns: the multi-turn count
    ssi       prenc_ssi: what the SSI slave sends
    biss      prenc_biss: BiSS-C frames and CRC
    protocol  prenc_frame_rx / prenc_frame_tx / prenc_host_link: frames and payloads
    host      `prenc host`: the PC side of the UART link
"""
