// Sources of prenc_track_monitor, relative to this folder (verilator -F, or -f from rtl/).
prenc_track_monitor.v
