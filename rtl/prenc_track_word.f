// Sources of prenc_track_word, relative to this folder.
prenc_track_word.v
