# SPDX-License-Identifier: Apache-2.0
"""The `prenc` command line and the jobs it runs.

    main       `prenc` and its subcommands
    arguments  argument types shared by the subcommands
    disc       printable discs (SVG, PNG)
    demo       `prenc demo`: the model on the virtual encoder
    core_demo  the figures of `make demo` for the core
"""
