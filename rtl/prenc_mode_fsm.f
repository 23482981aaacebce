// Sources of prenc_mode_fsm, relative to this folder (verilator -F, or -f from rtl/).
prenc_mode_fsm.v
