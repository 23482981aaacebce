# SPDX-License-Identifier: Apache-2.0
"""Models of the reader core's RTL (rtl/core/), module for module and clock for clock.

    input_conditioner  prenc_input_conditioner: synchronizers and glitch filters
    quadrature         prenc_quadrature: quarter index, steps, illegal transitions
    sampler            prenc_sampler: mid-slot strobes with direction and readings
    position           prenc_position: slot count, events, delayed output
    track_word         prenc_track_word: one head's code word and its evidence
    converter          prenc_converter: code word -> slot (and the serial converter)
    mode_fsm           prenc_mode_fsm: the judge of the offset, modes, pos_valid
    reader             prenc_core: the whole reader core
    lock_depth         how deep a lock must be: undetectable error patterns per N, k, rate
    front_end          the conditioner, decoder and sampler chained (prenc_core's front end)
"""
