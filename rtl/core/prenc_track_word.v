// SPDX-License-Identifier: Apache-2.0
// prenc_track_word: one head's code word in the reader's count space.
//
// The head's readings at the slot counts base .. base+N-1 form an N-bit word (the
// lowest count in the MSB, as w(p) on the disc); `index` = count - base is the
// head's place in it. A count move inside the window moves the index; past an end
// the window slides and the entering bit is the disc's law applied to the window
// (forward at the top, inverse at the bottom), so a window that holds the disc's
// bits keeps holding them.
//   raw mode  (acquiring): a strobe writes the reading at the index (known); at an
//             illegal quadrature transition the count may be a slot off (the other
//             way, every reading belongs one index further along the count's way), so
//             a bit stays known only where the bit that would take its place is known
//             and equal: right whichever way the disc went (none if the same clock
//             slides the window or writes, or with KEEP = 0; the window keeps its
//             place). Evidence is counted in distinct slots: ext_lo / ext_hi are
//             the slots just below / above the window whose last reading equals the
//             law's extension of the window (a slide over a known bit keeps it there,
//             a slide back takes it as known, a reading that changes the word empties
//             both), so a re-read after a reversal adds nothing. `span` = ext_lo +
//             ext_hi (saturating at EXT_MAX) of a full raw window. The health score
//             also counts raw disagreements (a reading that changes a window full
//             since the last flush), registered and scored on the next clock as the
//             law-mode comparisons are; `settled` (score 0) lets the head take part in a
//             lock. The score survives flushes: it is the head's record.
//   law mode  (locked): a strobe only compares the reading with the bit at the
//             index (mismatch) and with the bits one slot either side (mismatch_lo,
//             mismatch_hi: the other count hypothesis after a missed state). A
//             health score rises by SCORE_UP on a mismatch and falls by one on a
//             match; at SCORE_LIMIT the track stops supporting the position and goes
//             back to raw mode, to be read anew. While the judge holds two hypotheses
//             (dual), a reading where they predict different bits leaves the score.
// Timing: the ports' event is registered and applied on the clock after, one clock
// behind the count (prenc_core's latency 6 + FILTER), with what it selects (a count or
// index move, a slide, a raw write, the base's step) and `demote` registered ahead of
// it from the ports and the registers' next values: the word, the converter's address
// and the base start from registers. rst also empties the registered event and puts
// the base at HEAD_OFFSET: the count is reset with the track word (0 on every reset
// clock but the first; the core holds rst for 4 clocks).
// `addr` is the word after this clock, for the converter (a registered ROM read),
// so the converted slot arrives with `word`. base = count - index + HEAD_OFFSET
// makes `converted slot - base` the offset for either head.
// Model: prenc.track_word.TrackWord.
//
// Latency: a strobe's event is registered and applied on the clock after it, one clock
// behind the slot count (part of prenc_core's 6 + FILTER); `addr` is the word after
// this clock, for the converter's registered read.
//
// Parameters
//   N            code word length, 2..24
//   TAPS         feedback set as a mask, bit t-1 per tap t (default disc: 32'h204)
//   HEAD_OFFSET  0 for head 1 (reads s(p)), N-1 for head 2 (reads s(p+N-1))
//   SCORE_UP     score added by a mismatch, 1..15
//   SCORE_LIMIT  score at which the track stops supporting, SCORE_UP..255
//   ERROR_WIDTH  mismatch counter width, 1..32 (saturates)
//   EXT_MAX      span saturation, 1..63 (the deepest lock's need)
//   QUIET        agreeing checks after which a head is quiet, 1..63 (default 4N)
//   KEEP         1: a missed state in raw mode keeps the readings right either way;
//                0: it forgets them all (the core's HYPOTHESES = 0)
//
// Ports
//   strobe, head             a mid-slot strobe and this head's reading
//   up, down, illegal        the count moved (an illegal step may come with a move)
//   illegal_cw               the way the count took at the illegal step (CW: + 2 quarters)
//   slot                     the count after this clock's move
//                            (these seven: applied on the next clock)
//   flush, law_on            from the judge: empty to raw mode / turn to law mode
//   realign_up, realign_down from the judge: move the index one slot, on the first
//                            clock without an event after the pulse (the other
//                            hypothesis won)
//   dual, dual_cw            from the judge: two hypotheses open, the count's way
//   span, settled, quiet     lock evidence of a raw window and of its head (from registers):
//                            quiet = no disagreement in the last QUIET checks, or since reset
//   steady                   the window's offset (converted slot - base) is the last
//                            clock's too: no reading changed the word, no realignment,
//                            flush or reset moved it (a slide or a move keeps it: the law
//                            extends any word to the disc's next window). The judge reads
//                            a track's offset only while steady, so that the core may
//                            register the converter's output (CONV_REG) and give it the
//                            last clock's offset without changing a decision.
//   word, full, base, law, supported, strobe_q, checked, mismatch*, errors: registered
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_track_word #(
  parameter integer N           = 10,
  parameter [31:0]  TAPS        = 32'h0000_0204,
  parameter integer HEAD_OFFSET = 0,
  parameter integer SCORE_UP    = 4,
  parameter integer SCORE_LIMIT = 12,
  parameter integer ERROR_WIDTH = 16,
  parameter integer EXT_MAX     = N + 1,
  parameter integer QUIET       = (4 * N > 63) ? 63 : 4 * N,
  parameter integer KEEP        = 1
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   strobe,
  input  wire                   head,
  input  wire                   up,
  input  wire                   down,
  input  wire                   illegal,
  input  wire                   illegal_cw,
  input  wire [N-1:0]           slot,
  input  wire                   flush,
  input  wire                   law_on,
  input  wire                   realign_up,
  input  wire                   realign_down,
  input  wire                   dual,
  input  wire                   dual_cw,
  input  wire                   clear_errors,
  output wire [N-1:0]           addr,
  output wire [N-1:0]           word,
  output wire                   full,
  output wire [N-1:0]           base,
  output wire                   law,
  output wire                   supported,
  output wire                   strobe_q,
  output wire                   checked,
  output wire                   mismatch,
  output wire                   mismatch_lo,
  output wire                   mismatch_hi,
  output wire [ERROR_WIDTH-1:0] errors,
  output wire [5:0]             span,
  output wire                   settled,
  output wire                   quiet,
  output wire                   steady
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_track_word_parameter_N_out_of_range_2_to_24 u_stop ();
    end else if (TAPS[N-1] != 1'b1 || (TAPS >> N) != 32'd0 || TAPS[N-2:0] == 0) begin : g_bad_taps
      initial $display("ERROR: %m: parameter TAPS = 'h%0h is not a feedback set for N = %0d",
                       TAPS, N);
      prenc_track_word_parameter_TAPS_not_a_feedback_set_for_N u_stop ();
    end
    if (KEEP != 0 && KEEP != 1) begin : g_bad_keep
      initial $display("ERROR: %m: parameter KEEP = %0d must be 0 or 1", KEEP);
      prenc_track_word_parameter_KEEP_must_be_0_or_1 u_stop ();
    end
    if (HEAD_OFFSET != 0 && HEAD_OFFSET != N - 1) begin : g_bad_head_offset
      initial $display("ERROR: %m: parameter HEAD_OFFSET = %0d must be 0 or N-1", HEAD_OFFSET);
      prenc_track_word_parameter_HEAD_OFFSET_must_be_0_or_N_minus_1 u_stop ();
    end
    if (SCORE_UP < 1 || SCORE_UP > 15 || SCORE_LIMIT < SCORE_UP ||
        SCORE_LIMIT > 255) begin : g_bad_score
      initial $display({"ERROR: %m: parameters SCORE_UP = %0d, SCORE_LIMIT = %0d: ",
                        "need 1 <= UP <= 15, UP <= LIMIT <= 255"},
                       SCORE_UP, SCORE_LIMIT);
      prenc_track_word_parameter_SCORE_UP_or_SCORE_LIMIT_out_of_range u_stop ();
    end
    if (QUIET < 1 || QUIET > 63) begin : g_bad_quiet
      initial $display("ERROR: %m: parameter QUIET = %0d is out of range 1..63", QUIET);
      prenc_track_word_parameter_QUIET_out_of_range_1_to_63 u_stop ();
    end
    if (EXT_MAX < 1 || EXT_MAX > 63) begin : g_bad_ext_max
      initial $display("ERROR: %m: parameter EXT_MAX = %0d is out of range 1..63", EXT_MAX);
      prenc_track_word_parameter_EXT_MAX_out_of_range_1_to_63 u_stop ();
    end
    if (ERROR_WIDTH < 1 || ERROR_WIDTH > 32) begin : g_bad_error_width
      initial $display("ERROR: %m: parameter ERROR_WIDTH = %0d is out of range 1..32", ERROR_WIDTH);
      prenc_track_word_parameter_ERROR_WIDTH_out_of_range_1_to_32 u_stop ();
    end
  endgenerate

  localparam integer SW = $clog2(SCORE_LIMIT + 1);
  localparam [N-1:0] INDEX0  = {1'b1, {(N - 1){1'b0}}};  // at_index_reg at index 0
  localparam [31:0]  HO32    = HEAD_OFFSET;
  localparam [31:0]  UP32    = SCORE_UP;
  localparam [31:0]  LIMIT32 = SCORE_LIMIT;
  localparam [SW-1:0] S_UP    = UP32[SW-1:0];
  localparam [SW-1:0] S_LIMIT = LIMIT32[SW-1:0];
  localparam [31:0]  EXT32   = EXT_MAX;
  localparam integer EW      = $clog2(EXT_MAX + 1);  // the evidence counters' width
  localparam [EW-1:0] E_MAX  = EXT32[EW-1:0];
  localparam [31:0]  QUIET32 = QUIET;
  localparam integer QW      = $clog2(QUIET + 1);
  localparam [QW-1:0] Q_MAX  = QUIET32[QW-1:0];

  reg [N-1:0]           word_reg;
  reg [N-1:0]           known_reg;
  reg [N-1:0]           at_index_reg;  // the index one-hot: bit N-1-i at index i
  reg                   law_reg;
  reg [N-1:0]           base_reg;
  reg                   strobe_reg;
  reg                   checked_reg;
  reg                   mismatch_reg;
  reg                   mismatch_lo_reg;
  reg                   mismatch_hi_reg;
  reg [SW-1:0]          score_reg;
  reg [1:0]             pending_reg;  // {up, down}
  reg [ERROR_WIDTH-1:0] errors_reg;
  reg [EW-1:0]          ext_lo_reg;
  reg [EW-1:0]          ext_hi_reg;
  reg                   primed_reg;  // full since the last flush: every bit read or predicted
  reg [QW-1:0]          quiet_reg;   // agreeing checks since the head's last disagreement
  reg                   supported_reg;  // law mode and score below the limit
  reg                   full_reg;       // &known_reg
  reg                   raw_checked_reg;  // raw mode: a bit read or predicted was read again
  reg                   raw_changed_reg;  // ... and the reading changed it
  reg                   steady_reg;       // the offset is the last clock's

  // The disc's laws on the window (datasheet; the bracket is the de Bruijn term),
  // registered with the word (fwd_bit, inv_bit): off the path from the word to the
  // converter's address.
  reg  [N-1:0] at_index_next;
  reg  fwd_bit;
  reg  inv_bit;
  wire at_top    = at_index_reg[0];      // index N - 1
  wire at_bottom = at_index_reg[N-1];    // index 0
  // Index i is word bit N-1-i (the window in count order): at_index_reg bit N-1-i.
  wire [N-1:0] at_index = at_index_reg;
  wire bit_here = |(word_reg & at_index);
  wire bit_lo   = at_bottom ? inv_bit : |(word_reg & {at_index[N-2:0], 1'b0});
  wire bit_hi   = at_top ? fwd_bit : |(word_reg & {1'b0, at_index[N-1:1]});

  // The ports' event is the next clock's: it is registered here (strobe_d ... slot_d)
  // and applied on the clock after, one clock behind the count. What it selects (a
  // count or index move, a slide, a raw write, the base's step) is registered with it,
  // from the ports and the registers' next values (the *_ahead wires below), so that
  // the word, the converter's address and the base start from registers.
  reg         strobe_d;
  reg         illegal_d;
  reg         illegal_cw_d;
  reg         head_d;
  reg [N-1:0] slot_d;
  reg         idle_reg;
  reg         ev_up_reg;
  reg         ev_down_reg;
  reg         idx_up_reg;
  reg         idx_down_reg;
  reg         slide_up_reg;
  reg         slide_down_reg;
  reg         write_raw_reg;
  reg         base_inc_reg;
  reg         base_dec_reg;

  // A realignment waits in pending_reg and takes the first clock without an event
  // after the judge's pulse.
  wire       idle    = idle_reg;     // ~(up_d | down_d | strobe_d)
  wire       ev_up   = ev_up_reg;    // up_d | (idle & pending_reg[1])
  wire       ev_down = ev_down_reg;  // down_d | (idle & pending_reg[0])

  // Health, from last clock's comparison.
  // base = slot_d - index + HEAD_OFFSET, kept by steps: the count's move less the
  // index's, both at most one slot, so the sum is one of three values computed in
  // parallel from registers; a flush (or reset) puts the index at 0.
  wire         idx_up   = idx_up_reg;    // ev_up & ~at_top
  wire         idx_down = idx_down_reg;  // ~ev_up & ev_down & ~at_bottom
  wire         base_inc = base_inc_reg;  // (up_d & ~idx_up) | (~up_d & ~down_d & idx_down)
  wire         base_dec = base_dec_reg;  // (down_d & ~idx_down) | (~up_d & ~down_d & idx_up)
  wire         base_back  = base_dec & ~base_inc;  // (both only with up and down at once)
  wire [N-1:0] base_step  = base_reg + {{(N - 1){base_back}}, base_inc | base_dec};  // one adder
  wire [N-1:0] base_home  = slot_d + HO32[N-1:0];
  wire [N-1:0] base_next  = rst ? HO32[N-1:0] : (flush | demote) ? base_home : base_step;

  wire [SW:0] score_plus = {1'b0, score_reg} + {1'b0, S_UP};
  reg  [SW-1:0] score_next;
  reg  [QW-1:0] quiet_law;
  wire alt_reg = dual_cw ? mismatch_lo_reg : mismatch_hi_reg;
  wire [QW-1:0] quiet_up = (quiet_reg == Q_MAX) ? Q_MAX : quiet_reg + 1'b1;
  // Last clock's check of the head: law mode (unless the two hypotheses of a missed
  // state predict different bits there) or raw mode; never both on one clock.
  wire scored    = (checked_reg & ~(dual & (mismatch_reg != alt_reg))) | raw_checked_reg;
  wire disagreed = checked_reg ? mismatch_reg : raw_changed_reg;
  always @* begin
    score_next = score_reg;
    quiet_law  = quiet_reg;
    if (scored) begin
      quiet_law = disagreed ? {QW{1'b0}} : quiet_up;
      if (disagreed) begin
        score_next = (score_plus > {1'b0, S_LIMIT}) ? S_LIMIT : score_plus[SW-1:0];
      end else if (score_reg != {SW{1'b0}}) begin
        score_next = score_reg - 1'b1;
      end
    end
  end
  reg  demote_reg;
  wire demote = demote_reg;  // law_reg & (score_reg >= S_LIMIT), registered ahead

  // The word changes in one of three ways (never two at once): a slide past the top
  // or the bottom, or a raw strobe's write (a strobe is never idle: no realignment).
  // Each way's word, its laws and &known are computed from registers, and the way is
  // chosen last: the next word goes to the converter's address.
  wire slide_up   = slide_up_reg;    // ev_up & at_top
  wire slide_down = slide_down_reg;  // ~ev_up & ev_down & at_bottom
  wire write_raw  = write_raw_reg;   // strobe_d & ~up_d & ~down_d & ~law_reg
  wire [N-1:0] word_up    = {word_reg[N-2:0], fwd_bit};
  wire [N-1:0] word_down  = {inv_bit, word_reg[N-1:1]};
  wire [N-1:0] word_write = (word_reg & ~at_index) | (at_index & {N{head_d}});
  wire [N-1:0] word_next  = slide_up ? word_up : slide_down ? word_down :
                            write_raw ? word_write : word_reg;
  // At an illegal step without a slide or a write: the bits whose neighbour against the
  // count's way (index i - 1 when the count took the CW step; index i's bit is word bit
  // N-1-i) is known and equal. agree[b]: word bits b and b + 1 both known and equal.
  wire [N-1:0] agree      = {1'b0, known_reg[N-1:1] & known_reg[N-2:0] &
                                   ~(word_reg[N-1:1] ^ word_reg[N-2:0])};
  wire [N-1:0] kept       = illegal_cw_d ? agree : {agree[N-2:0], 1'b0};
  // A slide keeps the law's own bit at the end it leaves: inv(word_up) is the bit
  // slid out, word_reg[N-1], and fwd(word_down) is word_reg[0] (every word is a window
  // of the disc; the proofs check it).
  wire fwd_up, inv_up_law, fwd_down_law, inv_down, fwd_write, inv_write;
  prenc_disc_law #(.N (N), .TAPS (TAPS)) u_law_up (
    .word (word_up), .forward_bit (fwd_up), .inverse_bit (inv_up_law));
  prenc_disc_law #(.N (N), .TAPS (TAPS)) u_law_down (
    .word (word_down), .forward_bit (fwd_down_law), .inverse_bit (inv_down));
  prenc_disc_law #(.N (N), .TAPS (TAPS)) u_law_write (
    .word (word_write), .forward_bit (fwd_write), .inverse_bit (inv_write));
  wire unused_laws = &{1'b0, inv_up_law, fwd_down_law};
  wire fwd_next   = write_raw ? fwd_write : slide_up ? fwd_up :
                    slide_down ? word_reg[0] : fwd_bit;
  wire inv_next   = write_raw ? inv_write : slide_up ? word_reg[N-1] :
                    slide_down ? inv_down : inv_bit;
  wire full_after = slide_up   ? ((&known_reg[N-2:0]) & (ext_hi_reg != {EW{1'b0}})) :
                    slide_down ? ((&known_reg[N-1:1]) & (ext_lo_reg != {EW{1'b0}})) :
                    write_raw  ? (&(known_reg | at_index)) : (&known_reg);

  wire        changed        = head_d ^ bit_here;
  // A slide moves both ext counters one slot, opposite ways: one adder each.
  localparam [EW-1:0] E_ONE = 1;
  wire [EW-1:0] ext_lo_step  = ext_lo_reg + (ev_up ? E_ONE : {EW{1'b1}});  // +1 up, -1 down
  wire [EW-1:0] ext_hi_step  = ext_hi_reg + (ev_up ? {EW{1'b1}} : E_ONE);  // -1 up, +1 down

  reg [N-1:0]  known_next;
  reg          law_next;
  reg [SW-1:0] score_after;
  reg [1:0]    pending_next;
  reg [EW-1:0] ext_lo_next;
  reg [EW-1:0] ext_hi_next;
  reg          primed_next;
  reg [QW-1:0] quiet_next;
  always @* begin
    known_next   = known_reg;
    at_index_next = idx_up ? {1'b0, at_index_reg[N-1:1]} :
                    idx_down ? {at_index_reg[N-2:0], 1'b0} : at_index_reg;
    law_next     = law_reg;
    score_after  = score_next;
    pending_next = (idle ? 2'b00 : pending_reg) | {realign_up, realign_down};
    ext_lo_next  = ext_lo_reg;
    ext_hi_next  = ext_hi_reg;
    quiet_next   = quiet_law;
    if (slide_up) begin
      known_next  = {known_reg[N-2:0], ext_hi_reg != {EW{1'b0}}};
      ext_lo_next = !known_reg[N-1] ? {EW{1'b0}} : (ext_lo_reg == E_MAX) ? E_MAX : ext_lo_step;
      ext_hi_next = (ext_hi_reg == {EW{1'b0}}) ? {EW{1'b0}} : ext_hi_step;
    end else if (slide_down) begin
      known_next  = {ext_lo_reg != {EW{1'b0}}, known_reg[N-1:1]};
      ext_hi_next = !known_reg[0] ? {EW{1'b0}} : (ext_hi_reg == E_MAX) ? E_MAX : ext_hi_step;
      ext_lo_next = (ext_lo_reg == {EW{1'b0}}) ? {EW{1'b0}} : ext_lo_step;
    end else if (write_raw) begin
      known_next = known_reg | at_index;
      if (changed) begin
        ext_lo_next = {EW{1'b0}};
        ext_hi_next = {EW{1'b0}};
      end
    end
    if (law_reg) begin
      ext_lo_next = {EW{1'b0}};
      ext_hi_next = {EW{1'b0}};
    end
    primed_next = primed_reg | full_after;
    if (illegal_d && !law_reg) begin
      // The count may be a slot off: a bit stays known where the bit that would take
      // its place the other way (index - 1 when the count took the CW step) is known
      // and equal to it; none when this clock slides the window or writes a reading.
      // The rest are in doubt, not the window's place.
      known_next  = (KEEP == 0 || slide_up || slide_down || write_raw) ? {N{1'b0}} : kept;
      ext_lo_next = {EW{1'b0}};
      ext_hi_next = {EW{1'b0}};
      primed_next = 1'b0;
    end
    if (law_on) begin
      law_next    = 1'b1;
      score_after = {SW{1'b0}};
    end
    if (flush || demote) begin  // the score stays: it is the head's record
      known_next   = {N{1'b0}};
      at_index_next = INDEX0;
      law_next     = 1'b0;
      pending_next = 2'b00;
      ext_lo_next  = {EW{1'b0}};
      ext_hi_next  = {EW{1'b0}};
      primed_next  = 1'b0;
    end
  end

  // The selects of the next clock, from the ports and the registers' next values.
  wire [N-1:0] at_index_ahead = rst ? INDEX0 : at_index_next;
  wire [1:0]   pending_ahead  = rst ? 2'b00 : pending_next;
  wire         law_ahead      = ~rst & law_next;
  wire [SW-1:0] score_ahead   = rst ? {SW{1'b0}} : score_after;
  wire         top_ahead      = at_index_ahead[0];
  wire         bottom_ahead   = at_index_ahead[N-1];
  wire         strobe_ahead   = strobe & ~rst;  // the delayed event is reset with the rest
  wire         up_ahead       = up & ~rst;
  wire         down_ahead     = down & ~rst;
  wire         idle_ahead     = ~(up_ahead | down_ahead | strobe_ahead);
  wire         ev_up_ahead    = up_ahead | (idle_ahead & pending_ahead[1]);
  wire         ev_down_ahead  = down_ahead | (idle_ahead & pending_ahead[0]);
  wire         idx_up_ahead   = ev_up_ahead & ~top_ahead;
  wire         idx_down_ahead = ~ev_up_ahead & ev_down_ahead & ~bottom_ahead;
  always @(posedge clk) begin
    strobe_d       <= strobe_ahead;
    illegal_d      <= illegal & ~rst;
    illegal_cw_d   <= illegal_cw & ~rst;
    head_d         <= head & ~rst;
    slot_d         <= rst ? {N{1'b0}} : slot;
    idle_reg       <= idle_ahead;
    ev_up_reg      <= ev_up_ahead;
    ev_down_reg    <= ev_down_ahead;
    idx_up_reg     <= idx_up_ahead;
    idx_down_reg   <= idx_down_ahead;
    slide_up_reg   <= ev_up_ahead & top_ahead;
    slide_down_reg <= ~ev_up_ahead & ev_down_ahead & bottom_ahead;
    write_raw_reg  <= strobe_ahead & ~up_ahead & ~down_ahead & ~law_ahead;
    base_inc_reg   <= (up_ahead & ~idx_up_ahead) | (~up_ahead & ~down_ahead & idx_down_ahead);
    base_dec_reg   <= (down_ahead & ~idx_down_ahead) | (~up_ahead & ~down_ahead & idx_up_ahead);
    demote_reg     <= law_ahead & (score_ahead >= S_LIMIT);
  end

  always @(posedge clk) begin
    word_reg        <= word_next;
    fwd_bit         <= fwd_next;
    inv_bit         <= inv_next;
    known_reg       <= known_next;
    at_index_reg    <= at_index_next;
    law_reg         <= law_next;
    score_reg       <= score_after;
    pending_reg     <= pending_next;
    ext_lo_reg      <= ext_lo_next;
    ext_hi_reg      <= ext_hi_next;
    primed_reg      <= primed_next;
    quiet_reg       <= quiet_next;
    full_reg        <= full_after & ~(illegal_d & ~law_reg) & ~flush & ~demote;  // = &known_next
    supported_reg   <= law_next & (score_after < S_LIMIT);
    raw_checked_reg <= strobe_d & ~law_reg & ~ev_up & ~ev_down & primed_reg & ~law_on;
    raw_changed_reg <= changed;
    steady_reg      <= ~(write_raw & changed) & ~(idle & (|pending_reg)) & ~flush & ~demote;
    base_reg        <= base_next;  // = slot_d - index_next + HEAD_OFFSET
    strobe_reg      <= strobe_d;
    checked_reg     <= strobe_d & law_reg;
    mismatch_reg    <= strobe_d & law_reg & (head_d ^ bit_here);
    mismatch_lo_reg <= strobe_d & law_reg & (head_d ^ bit_lo);
    mismatch_hi_reg <= strobe_d & law_reg & (head_d ^ bit_hi);
    if (checked_reg && mismatch_reg && errors_reg != {ERROR_WIDTH{1'b1}}) begin
      errors_reg <= errors_reg + 1'b1;
    end
    if (clear_errors) begin
      errors_reg <= {ERROR_WIDTH{1'b0}};
    end
    if (rst) begin
      known_reg       <= {N{1'b0}};
      at_index_reg    <= INDEX0;
      // The all-zero word and its laws: 0^N is followed and preceded by a 1 on
      // every de Bruijn disc. The laws then stay the word's (each way the word
      // changes computes them; holding keeps them).
      word_reg        <= {N{1'b0}};
      fwd_bit         <= 1'b1;
      inv_bit         <= 1'b1;
      law_reg         <= 1'b0;
      score_reg       <= {SW{1'b0}};
      pending_reg     <= 2'b00;
      ext_lo_reg      <= {EW{1'b0}};
      ext_hi_reg      <= {EW{1'b0}};
      primed_reg      <= 1'b0;
      quiet_reg       <= Q_MAX;
      supported_reg   <= 1'b0;
      full_reg        <= 1'b0;
      raw_checked_reg <= 1'b0;
      raw_changed_reg <= 1'b0;
      steady_reg      <= 1'b0;
      strobe_reg      <= 1'b0;
      checked_reg     <= 1'b0;
      mismatch_reg    <= 1'b0;
      mismatch_lo_reg <= 1'b0;
      mismatch_hi_reg <= 1'b0;
      errors_reg      <= {ERROR_WIDTH{1'b0}};
    end
  end

  assign addr        = word_next;
  assign word        = word_reg;
  assign full        = full_reg;
  assign steady      = steady_reg;
  assign base        = base_reg;
  assign law         = law_reg;
  assign supported   = supported_reg;
  assign strobe_q    = strobe_reg;
  assign checked     = checked_reg;
  assign mismatch    = mismatch_reg;
  assign mismatch_lo = mismatch_lo_reg;
  assign mismatch_hi = mismatch_hi_reg;
  assign errors      = errors_reg;
  wire [EW:0]   ext_sum  = {1'b0, ext_lo_reg} + {1'b0, ext_hi_reg};
  wire [EW-1:0] span_w   = (~full_reg | law_reg) ? {EW{1'b0}} :
                           (ext_sum > {1'b0, E_MAX}) ? E_MAX : ext_sum[EW-1:0];
  generate
    if (EW < 6) begin : g_span_narrow
      assign span = {{(6 - EW){1'b0}}, span_w};
    end else begin : g_span_full
      assign span = span_w;
    end
  endgenerate
  assign settled     = (score_reg == {SW{1'b0}});
  assign quiet       = (quiet_reg == Q_MAX);

`ifdef FORMAL
  // Properties (formal/prenc_track_word.sby), against a disc built from the datasheet
  // (formal/prenc_disc_reference.vh), not from the law: a window that is W(p) slides
  // to W(p + 1) past its top and to W(p - 1) past its bottom (so a slide back undoes a
  // slide forward); a raw strobe writes the reading at the index; a law-mode strobe
  // compares the reading with the disc's bit at the index, and with the bits one slot
  // either side; base = count - index + HEAD_OFFSET.
  `include "prenc_disc_reference.vh"
  function automatic [N-1:0] f_pos;  // the slot whose window is w (every word is one)
    input [N-1:0] w;
    integer p;
    begin
      f_pos = {N{1'b0}};
      for (p = 0; p < F_L; p = p + 1) begin
        if (f_window(p) == w) f_pos = p[N-1:0];
      end
    end
  endfunction
  function automatic f_bit;  // s(p) on the reference disc, p modulo 2^N
    input [N-1:0] p;
    begin
      f_bit = F_S[p];
    end
  endfunction
  localparam integer IW = (N <= 2) ? 1 : $clog2(N);
  localparam [31:0]  LAST32 = N - 1;
  localparam [IW-1:0] LAST  = LAST32[IW-1:0];
  wire [N-1:0] in_order;  // the window in count order
  genvar g;
  generate
    for (g = 0; g < N; g = g + 1) begin : g_order
      assign in_order[g] = word_reg[N-1-g];
    end
  endgenerate
  function automatic [IW-1:0] f_index_of;  // the index of the one-hot
    input [N-1:0] at;
    integer i;
    begin
      f_index_of = {IW{1'b0}};
      for (i = 0; i < N; i = i + 1) begin
        if (at[N - 1 - i]) f_index_of = i[IW-1:0];
      end
    end
  endfunction
  wire [IW-1:0] index_reg = f_index_of(at_index_reg);
  reg f_past_valid = 1'b0;
  reg f_rst_prev = 1'b0;
  reg [N-1:0] f_slot_prev;
  reg [N-1:0] f_slot_d_prev;
  always @(posedge clk) begin
    f_past_valid  <= 1'b1;
    f_rst_prev    <= rst;
    f_slot_prev   <= slot;
    f_slot_d_prev <= slot_d;
  end
  // A slide keeps the law's bit at the end it leaves (every word is a window, and
  // the registered laws are the word's since reset).
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      assert (inv_up_law == word_reg[N-1] && fwd_down_law == word_reg[0]);
    end
  end
  initial assume (rst);
  // The core's count: it moves one slot with up or down, otherwise it holds; it is
  // reset with the track word (prenc_position, the same rst), so it is 0 on every
  // reset clock but the first, and a reset lasts two clocks at least (the core's, 4).
  reg f_rst_prev2 = 1'b0;
  always @(posedge clk) f_rst_prev2 <= f_rst_prev;
  always @(*) begin
    if (f_past_valid && f_rst_prev && !f_rst_prev2) assume (rst);
    if (f_past_valid && f_rst_prev && rst) assume (slot == {N{1'b0}});
    assume (!(up && down));
    if (f_past_valid) begin
      if (up) assume (slot == f_slot_prev + 1'b1);
      else if (down) assume (slot == f_slot_prev - 1'b1);
      else assume (slot == f_slot_prev);
    end
  end
  // Last clock's window and event.
  reg [N-1:0]  f_p_prev;      // the slot of last clock's window
  reg [IW-1:0] f_index_prev;
  reg          f_slide_up;
  reg          f_slide_down;
  reg          f_write;
  reg          f_head_prev;
  reg          f_clear_prev;   // a flush, a demotion or an illegal step in raw mode
  reg          f_law_strobe;
  always @(posedge clk) begin
    f_p_prev     <= f_pos(word_reg);
    f_index_prev <= index_reg;
    f_slide_up   <= ev_up && at_top;
    f_slide_down <= !ev_up && ev_down && at_bottom;
    f_write      <= !ev_up && !ev_down && strobe_d && !law_reg;
    f_head_prev  <= head_d;
    f_clear_prev <= flush || demote || (illegal_d && !law_reg);
    f_law_strobe <= strobe_d && law_reg;
  end
  wire [N-1:0] f_here = f_p_prev + {{(N - IW){1'b0}}, f_index_prev};
  // The registered selects are the applied event's, on the registers they act on.
  reg up_d;
  reg down_d;
  always @(posedge clk) begin
    up_d   <= up & ~rst;
    down_d <= down & ~rst;
  end
  always @(*) begin
    if (f_past_valid) begin
      assert (idle == !(up_d || down_d || strobe_d));
      assert (ev_up == (up_d || (idle && pending_reg[1])));
      assert (ev_down == (down_d || (idle && pending_reg[0])));
      assert (idx_up == (ev_up && !at_top) && idx_down == (!ev_up && ev_down && !at_bottom));
      assert (slide_up == (ev_up && at_top) && slide_down == (!ev_up && ev_down && at_bottom));
      assert (write_raw == (strobe_d && !up_d && !down_d && !law_reg));
      assert (base_inc == ((up_d && !idx_up) || (!up_d && !down_d && idx_down)));
      assert (base_dec == ((down_d && !idx_down) || (!up_d && !down_d && idx_up)));
      assert (demote == (law_reg && score_reg >= S_LIMIT));
    end
  end
  always @(*) begin
    if (f_past_valid) begin
      assert (at_index_reg != {N{1'b0}} && (at_index_reg & (at_index_reg - 1'b1)) == {N{1'b0}});
      assert (index_reg <= LAST);
      assert (at_top == (index_reg == LAST) && at_bottom == (index_reg == {IW{1'b0}}));
      assert (full_reg == (&known_reg));
      assert (supported == (law_reg && score_reg < S_LIMIT));
    end
    if (f_past_valid && !f_rst_prev) begin
      // The laws, registered with the word: the disc's bits after and before it.
      assert (fwd_bit == f_bit(f_pos(word_reg) + N[N-1:0]));
      assert (inv_bit == f_bit(f_pos(word_reg) - 1'b1));
      assert (base_reg == f_slot_d_prev - {{(N - IW){1'b0}}, index_reg} + HO32[N-1:0]);
      if (f_slide_up) assert (word_reg == f_window(f_p_prev + 1'b1));
      if (f_slide_down) assert (word_reg == f_window(f_p_prev - 1'b1));
      if (!f_slide_up && !f_slide_down && !f_write) assert (f_pos(word_reg) == f_p_prev);
      if (f_write) begin
        assert (in_order[f_index_prev] == f_head_prev);
        assert (known_reg[N - 1 - f_index_prev] || f_clear_prev);
      end
      if (f_law_strobe) begin
        assert (checked && mismatch == (f_head_prev ^ f_bit(f_here)));
        assert (mismatch_lo == (f_head_prev ^ f_bit(f_here - 1'b1)));
        assert (mismatch_hi == (f_head_prev ^ f_bit(f_here + 1'b1)));
      end else begin
        assert (!checked && !mismatch && !mismatch_lo && !mismatch_hi);
      end
    end
  end
  // The head's record: the score (+ SCORE_UP per disagreement, - 1 per agreement,
  // within 0..SCORE_LIMIT; zero when the track turns to law mode), the agreeing checks
  // since the last disagreement (up to QUIET), the error count; the lock evidence.
  wire f_alt    = dual_cw ? mismatch_lo : mismatch_hi;
  wire f_scored = (checked && !(dual && mismatch != f_alt)) || raw_checked_reg;
  wire f_dis    = checked ? mismatch : raw_changed_reg;
  reg          f_scored_prev;
  reg          f_dis_prev;
  reg          f_law_on_prev;
  reg          f_strobe_prev;
  reg          f_clear_errors_prev;
  reg          f_count_error;
  reg [SW-1:0] f_score_prev;
  reg [QW-1:0] f_quiet_prev;
  reg [ERROR_WIDTH-1:0] f_errors_prev;
  reg          f_raw_read;     // last clock: a raw strobe at a bit read or predicted before
  reg          f_raw_changed;  // ... that the reading changed
  always @(posedge clk) begin
    f_scored_prev       <= f_scored;
    f_dis_prev          <= f_dis;
    f_law_on_prev       <= law_on;
    f_strobe_prev       <= strobe_d;
    f_clear_errors_prev <= clear_errors;
    f_count_error       <= checked && mismatch;
    f_score_prev        <= score_reg;
    f_quiet_prev        <= quiet_reg;
    f_errors_prev       <= errors_reg;
    f_raw_read          <= strobe_d && !law_reg && !ev_up && !ev_down && primed_reg && !law_on;
    f_raw_changed       <= head_d != in_order[index_reg];
  end
  wire [SW:0]  f_score_up = {1'b0, f_score_prev} + {1'b0, S_UP};
  wire [6:0]   f_span_sum = {1'b0, ext_lo_reg} + {1'b0, ext_hi_reg};
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      assert (strobe_q == f_strobe_prev);
      assert (raw_checked_reg == f_raw_read && raw_changed_reg == f_raw_changed);
      if (f_law_on_prev) assert (score_reg == {SW{1'b0}});
      else if (f_scored_prev && f_dis_prev)
        assert (score_reg == ((f_score_up > {1'b0, S_LIMIT}) ? S_LIMIT : f_score_up[SW-1:0]));
      else if (f_scored_prev && f_score_prev != {SW{1'b0}})
        assert (score_reg == f_score_prev - 1'b1);
      else assert (score_reg == f_score_prev);
      if (f_scored_prev) begin
        assert (quiet_reg == (f_dis_prev ? {QW{1'b0}} :
                              (f_quiet_prev == Q_MAX) ? Q_MAX : f_quiet_prev + 1'b1));
      end else begin
        assert (quiet_reg == f_quiet_prev);
      end
      if (f_clear_errors_prev) assert (errors_reg == {ERROR_WIDTH{1'b0}});
      else if (f_count_error && f_errors_prev != {ERROR_WIDTH{1'b1}})
        assert (errors_reg == f_errors_prev + 1'b1);
      else assert (errors_reg == f_errors_prev);
    end
    if (f_past_valid) begin
      assert (settled == (score_reg == {SW{1'b0}}) && quiet == (quiet_reg == Q_MAX));
      assert (score_reg <= S_LIMIT && quiet_reg <= Q_MAX);
      assert (span == ((full_reg && !law_reg) ?
                       ((f_span_sum > {1'b0, E_MAX}) ? E_MAX : f_span_sum[5:0]) : 6'd0));
      if (f_rst_prev) assert (errors_reg == {ERROR_WIDTH{1'b0}} && score_reg == {SW{1'b0}} &&
                              quiet_reg == Q_MAX && !law_reg && known_reg == {N{1'b0}});
    end
  end
  // The lock evidence never overstates: in raw mode, every known bit of the window is
  // the head's last reading at its slot, and the ext_hi (ext_lo) slots above (below)
  // the window were last read as the disc continues (precedes) the window. Readings
  // are recorded as the design takes them (raw strobes on clocks without a move) and
  // forgotten where it forgets them (flush, demotion). A realignment (the judge found
  // the count one slot off) moves them one count with the window: down for
  // realign_up, up for realign_down. An illegal step in raw mode keeps a count's
  // reading only where the reading at the count before it (CW; after it, CCW) is
  // known and equal: the reading that would be there if the count is a slot off.
  reg  [F_L-1:0] f_rd;   // the last reading at each count
  reg  [F_L-1:0] f_has;  // read since the last clear
  wire [F_L-1:0] f_rot_rd  = (idle && pending_reg[1]) ? {f_rd[0], f_rd[F_L-1:1]} :
                             (idle && pending_reg[0]) ? {f_rd[F_L-2:0], f_rd[F_L-1]} : f_rd;
  wire [F_L-1:0] f_rot_has = (idle && pending_reg[1]) ? {f_has[0], f_has[F_L-1:1]} :
                             (idle && pending_reg[0]) ? {f_has[F_L-2:0], f_has[F_L-1]} : f_has;
  wire           f_wr      = !ev_up && !ev_down && strobe_d && !law_reg;
  wire [F_L-1:0] f_at      = {{(F_L - 1){1'b0}}, f_wr} << slot_d;
  wire [F_L-1:0] f_new_rd  = (f_rot_rd & ~f_at) | (f_at & {F_L{head_d}});
  wire [F_L-1:0] f_new_has = f_rot_has | f_at;
  wire [F_L-1:0] f_nb_rd   = illegal_cw_d ? {f_new_rd[F_L-2:0], f_new_rd[F_L-1]}   // count - 1
                                          : {f_new_rd[0], f_new_rd[F_L-1:1]};    // count + 1
  wire [F_L-1:0] f_nb_has  = illegal_cw_d ? {f_new_has[F_L-2:0], f_new_has[F_L-1]}
                                          : {f_new_has[0], f_new_has[F_L-1:1]};
  always @(posedge clk) begin
    f_rd  <= f_new_rd;
    f_has <= (rst || flush || demote) ? {F_L{1'b0}} :
             (illegal_d && !law_reg) ? (f_new_has & f_nb_has & ~(f_new_rd ^ f_nb_rd)) : f_new_has;
  end
  function automatic [1:0] f_read;  // {read since the last clear, last reading} at count c
    input [N-1:0] c;  // modulo 2^N
    begin
      f_read = {f_has[c], f_rd[c]};
    end
  endfunction
  wire [N-1:0] f_b0 = base_reg - HO32[N-1:0];  // the count of the window's first bit
  wire [N-1:0] f_p  = f_pos(word_reg);
  integer f_i;
  always @(*) begin
    if (f_past_valid && !f_rst_prev && !law_reg) begin
      for (f_i = 0; f_i < N; f_i = f_i + 1) begin
        if (known_reg[N - 1 - f_i]) begin
          assert (f_read(f_b0 + f_i) == {1'b1, in_order[f_i]});
        end
      end
      for (f_i = 0; f_i < EXT_MAX; f_i = f_i + 1) begin
        if (ext_hi_reg > f_i) begin
          assert (f_read(f_b0 + N + f_i) == {1'b1, f_bit(f_p + N + f_i)});
        end
        if (ext_lo_reg > f_i) begin
          assert (f_read(f_b0 - 1 - f_i) == {1'b1, f_bit(f_p - 1 - f_i)});
        end
      end
      assert (ext_lo_reg <= E_MAX && ext_hi_reg <= E_MAX);
    end
  end
  // The window's offset (its disc slot less its count) holds through every count move
  // and slide; a realignment, on the first clock without an event after the judge's
  // pulse, moves it one slot (+1 for realign_up); a write (raw mode) changes the word.
  reg  [1:0]   f_pend;  // {up, down} waiting for a clock without an event
  wire [N-1:0] f_woff = f_pos(word_reg) - f_b0;
  reg  [N-1:0] f_woff_prev;
  reg          f_moved_off;  // last clock: a realignment took effect, which way
  reg          f_realign_up_prev;
  reg          f_reset_prev;  // last clock: flush, demotion or reset (the window restarts)
  always @(posedge clk) begin
    f_pend            <= (idle ? 2'b00 : f_pend) | {realign_up, realign_down};
    f_woff_prev       <= f_woff;
    f_moved_off       <= idle && (f_pend != 2'b00);
    f_realign_up_prev <= f_pend[1];
    f_reset_prev      <= rst || flush || demote;
    if (rst || flush || demote) f_pend <= 2'b00;
  end
  // Law mode: on the judge's law_on; back to raw mode on a flush or at SCORE_LIMIT.
  reg f_law_expected;
  always @(posedge clk) begin
    f_law_expected <= !flush && !(law_reg && score_reg >= S_LIMIT) && (law_on || law_reg);
  end
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      assert (law_reg == f_law_expected);
      assert (pending_reg == f_pend);
      if (!f_reset_prev && !f_write) begin
        if (f_moved_off) assert (f_woff == (f_realign_up_prev ? f_woff_prev + 1'b1 :
                                                                f_woff_prev - 1'b1));
        else assert (f_woff == f_woff_prev);
      end
      // steady: the offset is the last clock's (the judge reads a lagging one by it).
      if (steady) assert (f_woff == f_woff_prev);
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (f_slide_up && law_reg);
      cover (f_slide_down && law_reg);
      cover (full_reg && !law_reg && span == 6'd3);
      cover (illegal_d && !law_reg && known_next != {N{1'b0}});  // readings kept at a missed state
      cover (demote);
      cover (supported && f_law_strobe && mismatch);
    end
  end
`endif

endmodule

`resetall
