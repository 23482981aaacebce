// SPDX-License-Identifier: Apache-2.0
// prenc_core: the reader of a pseudorandom absolute encoder, pins to verified position.
//
//   pins -> prenc_input_conditioner -> prenc_quadrature, and on the same edge
//           prenc_sampler (strobes) and prenc_position (count, events)
//        -> prenc_track_word x2 (each head's word in count space; raw or law mode)
//        -> prenc_converter x2 (each word -> slot, one clock)
//        -> J1 registers (each track's offset = converted slot - window base)
//        -> prenc_mode_fsm (the judge: offset, modes, pos_valid)
//        -> pos_abs = count + offset, at one latency
// See docs/architecture.md for the block diagram, the evidence rule and its
// arithmetic, the hypotheses after a missed quadrature state, and the timing.
//
// The position is the quadrature count plus an offset; the code proves the offset.
// Start-up: both heads' words agree on one offset over N + LOCK_BOTH - 1 distinct
// slots each (default N + 1 for N >= 8), or one head's word holds one offset over
// N + LOCK_ONE - 1 distinct slots (default 2N + 1), in either direction.
//
// Latency: pos_abs, pos_hyb and pos_valid show the pins as they were 6 + FILTER
// clocks earlier, all three aligned. Hold rst for at least 4 clocks.
//
// Parameters
//   N            code word length, 2..24 (2^N slots)
//   TAPS         feedback set as a mask, bit t-1 per tap t (default disc: 32'h204)
//   SHIFT        track 2 phase shift D; must be 2^(N-1) + N - 1, which puts head 2 on
//                the last bit of W(p) (the only geometry this reader decodes)
//   FILTER       glitch filter length in clocks, 0 (off)..65535; A and B are filtered as
//                one state, so that changes of both fewer than FILTER clocks apart are a
//                missed state in either order (a state must last FILTER clocks)
//   ROM_FILE     conversion table from `prenc rom --bits N --taps ... --format hex`
//   COUNT_WIDTH  incremental count width, 2..64
//   ERROR_WIDTH  error counter widths, 1..32
//   LOCK_BOTH    two-track lock: N + LOCK_BOTH - 1 consistent slots per track
//                (default 2 for N >= 8, 3 below: see docs/architecture.md)
//   LOCK_ONE     one-track lock: N + LOCK_ONE - 1 consistent slots
//                (default N + 2 for N >= 8, N + 5 below)
//   LOCK_EXTRA   slots more per track for a lock when a head had a disagreement in
//                its last 4N checks (3)
//   DUAL_VOTES   votes that decide between the two hypotheses of a missed state (3)
//   DUAL_SPAN    slots of travel the decision may take before the offset drops (12)
//   HYPOTHESES   1: a missed quadrature state opens the two hypotheses, and while
//                acquiring the windows keep the readings right either way; 0: it drops
//                the position until the next lock and empties the windows, with no
//                landing reading: about a fifth less logic, for sync tracks that never
//                miss a state (default 1)
//   SCORE_UP, SCORE_LIMIT   a track's health score: + SCORE_UP per mismatch, - 1 per
//                match, unsupported at SCORE_LIMIT (defaults 4, 12)
//   CONV_REG     1: the converters' output is registered before the offset's subtraction
//                (ECP5: its block RAM's clock-to-out without the output register is the
//                worst path); 0: subtracted straight from the block RAM (iCE40, default).
//                The same outputs either way (the judge reads an offset only while it
//                is steady); 1 costs 4N flip-flops
//
// Ports
//   head1, head2, sync_a, sync_b   raw asynchronous inputs (datasheet levels)
//   resolution     0: `position` is pos_abs (N bits); 1: pos_hyb (N+2 bits)
//   clear_errors   zero the error counters
//   pos_abs        absolute slot p
//   pos_hyb        hybrid position 4p + q
//   pos_valid      pos_abs and pos_hyb are a verified absolute position
//   mode           0 acquiring, 1 normal, 2 reduced (track 1 only),
//                  3 reduced (track 2 only), 4 incremental (position dropped, or two
//                  hypotheses open after a missed quadrature state)
//   position       pos_abs or pos_hyb as `resolution` selects, zero-extended
//   incremental    signed multi-turn count of quadrature steps since reset
//   direction      1: the last step was CW
//   track1_valid   pos_valid, and track 1 supports it (its law-mode word agrees)
//   track2_valid   the same for track 2
//   track1_pos, track2_pos   the position each track reads, valid with its flag
//   track1_errors, track2_errors   readings that disagreed with the prediction
//   sync_errors    illegal quadrature transitions
//   track1_error, track2_error   one clock: a reading of that head disagreed with the
//                  prediction and was corrected (what track1_errors, track2_errors count;
//                  never saturates): for prenc_health's warning
//   sync_step, sync_illegal   the quadrature decoder's registered step (its direction
//                  is `direction`) and illegal transition, each a one-clock pulse: the
//                  sync track's timing, for prenc_fine (velocity, fine position);
//                  pos_hyb shows a step 4 clocks later

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_core #(
  parameter integer N           = 10,
  parameter [31:0]  TAPS        = 32'h0000_0204,
  parameter integer SHIFT       = (1 << (N - 1)) + N - 1,
  parameter integer FILTER      = 2,
  parameter         ROM_FILE    = "prenc_rom_n10.hex",
  parameter integer COUNT_WIDTH = 32,
  parameter integer ERROR_WIDTH = 16,
  parameter integer LOCK_BOTH   = (N < 8) ? 3 : 2,
  parameter integer LOCK_ONE    = (N < 8) ? N + 5 : N + 2,
  parameter integer LOCK_EXTRA  = 3,
  parameter integer DUAL_VOTES  = 3,
  parameter integer DUAL_SPAN   = 12,
  parameter integer HYPOTHESES  = 1,
  parameter integer SCORE_UP    = 4,
  parameter integer SCORE_LIMIT = 12,
  parameter integer CONV_REG    = 0
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   head1,
  input  wire                   head2,
  input  wire                   sync_a,
  input  wire                   sync_b,
  input  wire                   resolution,
  input  wire                   clear_errors,
  output wire [N-1:0]           pos_abs,
  output wire [N+1:0]           pos_hyb,
  output wire                   pos_valid,
  output wire [2:0]             mode,
  output wire [N+1:0]           position,
  output wire [COUNT_WIDTH-1:0] incremental,
  output wire                   direction,
  output wire [N-1:0]           track1_pos,
  output wire                   track1_valid,
  output wire [N-1:0]           track2_pos,
  output wire                   track2_valid,
  output wire [ERROR_WIDTH-1:0] track1_errors,
  output wire [ERROR_WIDTH-1:0] track2_errors,
  output wire [ERROR_WIDTH-1:0] sync_errors,
  output wire                   track1_error,
  output wire                   track2_error,
  output wire                   sync_step,
  output wire                   sync_illegal
);

  generate
    if (N >= 2 && N <= 24 && SHIFT != (1 << (N - 1)) + N - 1) begin : g_bad_shift
      initial $display("ERROR: %m: parameter SHIFT = %0d must be 2^(N-1)+N-1 = %0d for N = %0d",
                       SHIFT, (1 << (N - 1)) + N - 1, N);
      prenc_core_parameter_SHIFT_must_be_2_pow_N_minus_1_plus_N_minus_1 u_stop ();
    end
    if (CONV_REG != 0 && CONV_REG != 1) begin : g_bad_conv_reg
      initial $display("ERROR: %m: parameter CONV_REG = %0d must be 0 or 1", CONV_REG);
      prenc_core_parameter_CONV_REG_must_be_0_or_1 u_stop ();
    end
  endgenerate

  // Pins: synchronizers and glitch filters.
  wire [3:0] clean;  // {B, A, head2, head1}

  prenc_input_conditioner #(
    .WIDTH  (4),
    .FILTER (FILTER),
    .PAIRED (1)        // A and B as one state: changes closer than FILTER are a missed state
  ) u_input_conditioner (
    .clk      (clk),
    .rst      (rst),
    .in_raw   ({sync_b, sync_a, head2, head1}),
    .in_clean (clean)
  );

  // Quadrature: quarter, steps, illegal transitions, the incremental count. The
  // sampler and the position take the decoded step on the decoder's own edge (its
  // *_next outputs): one clock of latency less than behind its registers.
  wire [1:0] quarter;  // the decoder's registered outputs: only step_cw is used (direction)
  wire       step;
  wire       step_cw;
  wire       illegal;
  wire [1:0] quarter_next;
  wire       step_next;
  wire       step_cw_next;
  wire       illegal_next;

  prenc_quadrature #(
    .COUNT_WIDTH (COUNT_WIDTH),
    .ERROR_WIDTH (ERROR_WIDTH)
  ) u_quadrature (
    .clk           (clk),
    .rst           (rst),
    .a             (clean[2]),
    .b             (clean[3]),
    .clear_errors  (clear_errors),
    .quarter       (quarter),
    .step          (step),
    .step_cw       (step_cw),
    .illegal       (illegal),
    .illegal_count (sync_errors),
    .count         (incremental),
    .quarter_next  (quarter_next),
    .step_next     (step_next),
    .step_cw_next  (step_cw_next),
    .illegal_next  (illegal_next)
  );

  // Mid-slot strobes with both heads.
  wire strobe;
  wire strobe_cw;  // for waveforms
  wire strobe_moved;  // for waveforms
  wire strobe_head1;
  wire strobe_head2;

  prenc_sampler #(
    .JUMP       (HYPOTHESES),  // the landing reading serves the hypotheses' votes
    .HEAD_DELAY (0)            // the step comes with the heads' sample
  ) u_sampler (
    .clk          (clk),
    .rst          (rst),
    .head1_in     (clean[0]),
    .head2_in     (clean[1]),
    .step         (step_next),
    .step_cw      (step_cw_next),
    .quarter      (quarter_next),
    .break_in     (illegal_next),
    .strobe       (strobe),
    .strobe_cw    (strobe_cw),
    .strobe_moved (strobe_moved),
    .strobe_head1 (strobe_head1),
    .strobe_head2 (strobe_head2)
  );

  // The count and the events (same clock as the strobe).
  wire [N-1:0] slot;
  wire         up;
  wire         down;
  wire         ev_illegal;
  wire         ev_illegal_cw;
  wire [N-1:0] slot_out;
  wire [1:0]   quarter_out;

  prenc_position #(
    .N (N)
  ) u_position (
    .clk           (clk),
    .rst           (rst),
    .quarter       (quarter_next),
    .step          (step_next),
    .step_cw       (step_cw_next),
    .illegal       (illegal_next),
    .slot          (slot),
    .up            (up),
    .down          (down),
    .ev_illegal    (ev_illegal),
    .ev_illegal_cw (ev_illegal_cw),
    .slot_out      (slot_out),
    .quarter_out   (quarter_out)
  );

  // One word per head, each with its converter.
  wire [1:0]   flush;
  wire [1:0]   law_on;
  wire         realign_up;
  wire         realign_down;
  wire [N-1:0] addr1;
  wire [N-1:0] addr2;
  wire [N-1:0] word1;  // for waveforms
  wire [N-1:0] word2;
  wire [1:0]   full;
  wire [N-1:0] base1;
  wire [N-1:0] base2;
  wire [1:0]   law;
  wire [1:0]   supported;
  wire         strobe_t;
  wire         strobe_t2;  // the same as strobe_t
  wire [1:0]   checked;
  wire [1:0]   mismatch;
  wire [1:0]   mismatch_lo;
  wire [1:0]   mismatch_hi;
  wire [5:0]   span1;
  wire [5:0]   span2;
  wire [1:0]   settled;
  wire [1:0]   quiet;
  wire [1:0]   steady;
  wire         dual;     // two hypotheses open (mode 4)
  wire         dual_cw;

  localparam integer EXT_MAX = ((LOCK_ONE > LOCK_BOTH) ? LOCK_ONE : LOCK_BOTH) - 1 + LOCK_EXTRA;

  prenc_track_word #(
    .N           (N),
    .TAPS        (TAPS),
    .HEAD_OFFSET (0),
    .SCORE_UP    (SCORE_UP),
    .SCORE_LIMIT (SCORE_LIMIT),
    .ERROR_WIDTH (ERROR_WIDTH),
    .EXT_MAX     (EXT_MAX),
    .KEEP        (HYPOTHESES)
  ) u_track1 (
    .clk          (clk),
    .rst          (rst),
    .strobe       (strobe),
    .head         (strobe_head1),
    .up           (up),
    .down         (down),
    .illegal      (ev_illegal),
    .illegal_cw   (ev_illegal_cw),
    .slot         (slot),
    .flush        (flush[0]),
    .law_on       (law_on[0]),
    .realign_up   (realign_up),
    .realign_down (realign_down),
    .dual         (dual),
    .dual_cw      (dual_cw),
    .clear_errors (clear_errors),
    .addr         (addr1),
    .word         (word1),
    .full         (full[0]),
    .base         (base1),
    .law          (law[0]),
    .supported    (supported[0]),
    .strobe_q     (strobe_t),
    .checked      (checked[0]),
    .mismatch     (mismatch[0]),
    .mismatch_lo  (mismatch_lo[0]),
    .mismatch_hi  (mismatch_hi[0]),
    .errors       (track1_errors),
    .span         (span1),
    .settled      (settled[0]),
    .quiet        (quiet[0]),
    .steady       (steady[0])
  );

  prenc_track_word #(
    .N           (N),
    .TAPS        (TAPS),
    .HEAD_OFFSET (N - 1),
    .SCORE_UP    (SCORE_UP),
    .SCORE_LIMIT (SCORE_LIMIT),
    .ERROR_WIDTH (ERROR_WIDTH),
    .EXT_MAX     (EXT_MAX),
    .KEEP        (HYPOTHESES)
  ) u_track2 (
    .clk          (clk),
    .rst          (rst),
    .strobe       (strobe),
    .head         (strobe_head2),
    .up           (up),
    .down         (down),
    .illegal      (ev_illegal),
    .illegal_cw   (ev_illegal_cw),
    .slot         (slot),
    .flush        (flush[1]),
    .law_on       (law_on[1]),
    .realign_up   (realign_up),
    .realign_down (realign_down),
    .dual         (dual),
    .dual_cw      (dual_cw),
    .clear_errors (clear_errors),
    .addr         (addr2),
    .word         (word2),
    .full         (full[1]),
    .base         (base2),
    .law          (law[1]),
    .supported    (supported[1]),
    .strobe_q     (strobe_t2),
    .checked      (checked[1]),
    .mismatch     (mismatch[1]),
    .mismatch_lo  (mismatch_lo[1]),
    .mismatch_hi  (mismatch_hi[1]),
    .errors       (track2_errors),
    .span         (span2),
    .settled      (settled[1]),
    .quiet        (quiet[1]),
    .steady       (steady[1])
  );

  wire [N-1:0] conv1;
  wire [N-1:0] conv2;
  wire         conv1_valid;  // always 1 after reset: every word is converted
  wire         conv2_valid;

  prenc_converter #(
    .N        (N),
    .ROM_FILE (ROM_FILE)
  ) u_converter1 (
    .clk        (clk),
    .rst        (rst),
    .word_valid (1'b1),
    .word       (addr1),
    .pos_valid  (conv1_valid),
    .pos        (conv1)
  );

  prenc_converter #(
    .N        (N),
    .ROM_FILE (ROM_FILE)
  ) u_converter2 (
    .clk        (clk),
    .rst        (rst),
    .word_valid (1'b1),
    .word       (addr2),
    .pos_valid  (conv2_valid),
    .pos        (conv2)
  );

  // The converted slots and the bases they go with: straight from the block RAMs, or
  // registered first (CONV_REG = 1), and then the J1 offsets are the words' of the
  // clock before, which the judge reads only while steady (the same as now).
  wire [N-1:0] conv1_j;
  wire [N-1:0] conv2_j;
  wire [N-1:0] base1_j;
  wire [N-1:0] base2_j;
  wire [4*N-1:0] conv_now = {conv1, conv2, base1, base2};
  generate
    if (CONV_REG == 1) begin : g_conv_reg
      reg [4*N-1:0] conv_reg;
      always @(posedge clk) conv_reg <= conv_now;
      assign {conv1_j, conv2_j, base1_j, base2_j} = conv_reg;
    end else begin : g_conv_direct
      assign {conv1_j, conv2_j, base1_j, base2_j} = conv_now;
    end
  endgenerate

  // Events carried alongside the track words (which apply each event a clock after
  // the count: the e registers), then the J1 registers: each track's offset and
  // evidence, one clock before the judge.
  reg         illegal_e_reg;
  reg         illegal_cw_e_reg;
  reg [N-1:0] slot_e_reg;
  reg         illegal_t_reg;
  reg         illegal_cw_t_reg;
  reg [N-1:0] slot_t_reg;
  reg         strobe_j_reg;
  reg         illegal_j_reg;
  reg         illegal_cw_j_reg;
  reg [N-1:0] slot_j_reg;
  reg [N-1:0] off1_j_reg;
  reg [N-1:0] off2_j_reg;

  always @(posedge clk) begin
    illegal_e_reg     <= ev_illegal;
    illegal_cw_e_reg  <= ev_illegal_cw;
    slot_e_reg        <= slot;
    illegal_t_reg     <= illegal_e_reg;
    illegal_cw_t_reg  <= illegal_cw_e_reg;
    slot_t_reg        <= slot_e_reg;
    strobe_j_reg      <= strobe_t;
    illegal_j_reg     <= illegal_t_reg;
    illegal_cw_j_reg  <= illegal_cw_t_reg;
    slot_j_reg        <= slot_t_reg;
    off1_j_reg        <= conv1_j - base1_j;
    off2_j_reg        <= conv2_j - base2_j;
    if (rst) begin
      illegal_e_reg     <= 1'b0;
      slot_e_reg        <= {N{1'b0}};
      illegal_t_reg     <= 1'b0;
      slot_t_reg        <= {N{1'b0}};
      strobe_j_reg      <= 1'b0;
      illegal_j_reg     <= 1'b0;
      illegal_cw_j_reg  <= 1'b0;
      slot_j_reg        <= {N{1'b0}};
      off1_j_reg        <= {N{1'b0}};
      off2_j_reg        <= {N{1'b0}};
    end
  end

  // The judge.
  wire [N-1:0] offset;

  prenc_mode_fsm #(
    .N          (N),
    .LOCK_BOTH  (LOCK_BOTH),
    .LOCK_ONE   (LOCK_ONE),
    .LOCK_EXTRA (LOCK_EXTRA),
    .DUAL_VOTES (DUAL_VOTES),
    .DUAL_SPAN  (DUAL_SPAN),
    .HYPOTHESES (HYPOTHESES)
  ) u_mode_fsm (
    .clk          (clk),
    .rst          (rst),
    .strobe       (strobe_j_reg),
    .illegal      (illegal_j_reg),
    .illegal_cw   (illegal_cw_j_reg),
    .slot         (slot_j_reg),
    .slot_ahead   (slot_t_reg[1:0]),
    .slot_ahead2  (slot_e_reg),
    .full_ahead   (full),
    .steady_ahead (steady),
    .off1         (off1_j_reg),
    .off2         (off2_j_reg),
    .span1_ahead   (span1),
    .span2_ahead   (span2),
    .settled_ahead (settled),
    .quiet_ahead   (quiet),
    .checked_ahead     (checked),
    .mismatch_ahead    (mismatch),
    .mismatch_lo_ahead (mismatch_lo),
    .mismatch_hi_ahead (mismatch_hi),
    .supported    (supported),
    .law          (law),
    .mode         (mode),
    .pos_valid    (pos_valid),
    .dual         (dual),
    .dual_cw      (dual_cw),
    .offset       (offset),
    .flush        (flush),
    .law_on       (law_on),
    .realign_up   (realign_up),
    .realign_down (realign_down)
  );

  wire unused_ok = &{1'b0, strobe_cw, strobe_moved, strobe_t2, word1, word2,
                     conv1_valid, conv2_valid, quarter};

  assign pos_abs      = slot_out + offset;
  assign pos_hyb      = {pos_abs, quarter_out};
  assign position     = resolution ? pos_hyb : {2'b00, pos_abs};
  assign direction    = step_cw;
  assign track1_error = checked[0] & mismatch[0];
  assign track2_error = checked[1] & mismatch[1];
  assign sync_step    = step;
  assign sync_illegal = illegal;
  assign track1_pos   = pos_abs;
  assign track2_pos   = pos_abs;
  assign track1_valid = pos_valid & supported[0];
  assign track2_valid = pos_valid & supported[1];

`ifdef FORMAL
  // Properties (formal/prenc_core.sby, bounded from reset: the whole core from its
  // pins), composed with the blocks' proofs (the judge's evidence, the count).
  reg f_past_valid = 1'b0;
  reg [3:0] f_since_rst = 4'd0;
  reg [2:0] f_rst_run = 3'd0;  // clocks of reset so far (up to 7), 0 at power-up
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_since_rst  <= rst ? 4'd0 : (f_since_rst == 4'd15) ? 4'd15 : f_since_rst + 1'b1;
    f_rst_run    <= !rst ? 3'd0 : (f_rst_run == 3'd7) ? f_rst_run : f_rst_run + 1'b1;
  end
  // Every reset, the one at power-up too (the flops start anywhere), lasts the
  // documented 4 clocks at least.
  always @(*) begin
    if (!f_past_valid || (f_rst_run != 3'd0 && f_rst_run < 3'd4)) assume (rst);
  end
  // The decoder's steps, delayed to meet the position (prenc_position: the count on
  // the decoder's edge, DECISION_DELAY = 4 more to slot_out).
  reg [4:0] f_step_d;
  reg [4:0] f_cw_d;
  reg [4:0] f_illegal_d;
  reg [N+1:0] f_hyb_prev;
  reg         f_valid_prev;
  reg [COUNT_WIDTH-1:0] f_inc_prev;
  reg         f_rst_last;  // rst on the clock before
  always @(posedge clk) begin
    f_step_d     <= {f_step_d[3:0], step_next};
    f_cw_d       <= {f_cw_d[3:0], step_cw_next};
    f_illegal_d  <= {f_illegal_d[3:0], illegal_next};
    f_hyb_prev   <= pos_hyb;
    f_valid_prev <= pos_valid;
    f_inc_prev   <= incremental;
    f_rst_last   <= rst;
  end
  always @(*) begin
    if (f_past_valid && f_since_rst >= 4'd7) begin
      // While valid, the position moves only with the quadrature: one quarter per
      // legal step, in its direction; an illegal transition clears pos_valid when the
      // count shows it.
      if (f_valid_prev && pos_valid) begin
        assert (!f_illegal_d[4]);
        if (f_step_d[4]) assert (pos_hyb == (f_cw_d[4] ? f_hyb_prev + 1'b1 : f_hyb_prev - 1'b1));
        else assert (pos_hyb == f_hyb_prev);
      end
      if (f_illegal_d[4]) assert (!pos_valid);
    end
    if (f_past_valid && !rst) begin
      assert (pos_valid == (mode == 3'd1 || mode == 3'd2 || mode == 3'd3));
      // The outputs made from the position claim no more than pos_valid: a track's
      // flag only with it (and with that track in law mode), its
      // position the core's, and `position` the one `resolution` selects.
      if (track1_valid) assert (pos_valid && law[0]);
      if (track2_valid) assert (pos_valid && law[1]);
      assert (track1_pos == pos_abs && track2_pos == pos_abs);
      assert (position == (resolution ? pos_hyb : {2'b00, pos_abs}));
    end
    // The incremental count: 0 after reset, then one up or down with each legal step
    // on the decoder's edge, and nothing else.
    if (f_past_valid && f_rst_last) assert (incremental == {COUNT_WIDTH{1'b0}});
    if (f_past_valid && !f_rst_last) begin
      if (f_step_d[0]) assert (incremental == (f_cw_d[0] ? f_inc_prev + 1'b1 : f_inc_prev - 1'b1));
      else assert (incremental == f_inc_prev);
    end
  end
`ifdef F_DISC
  // The pins read a disc (formal/prenc_disc_reference.vh, the datasheet's geometry):
  // its hybrid position f_h moves at most one quarter a clock, or two at once (a missed
  // state, A and B changing together) up to F_MISSED times; each head reads its bit,
  // head 1 s(p) and head 2 s(p + N - 1), flipped (a misread) up to F_MISREADS times
  // in all. The promise: a valid position is the disc's, at the core's latency.
  `include "prenc_disc_reference.vh"
  (* anyseq *) reg [1:0] f_move;   // 0 hold, 1 CW, 3 CCW, 2 two quarters (missed state)
  (* anyseq *) reg       f_jump_cw;
  (* anyseq *) reg [1:0] f_flip;   // misread head 2, head 1
  reg [N+1:0] f_h = {N+2{1'b0}};
  reg [3:0]   f_missed = 4'd0;
  reg [3:0]   f_misread = 4'd0;
  wire [N-1:0] f_p = f_h[N+1:2];
  wire [1:0]   f_q = f_h[1:0];
  wire [N-1:0] f_p2 = f_p + N[N-1:0] - 1'b1;
  always @(posedge clk) begin
    case (f_move)
      2'd1:    f_h <= f_h + 1'b1;
      2'd3:    f_h <= f_h - 1'b1;
      2'd2:    f_h <= f_jump_cw ? f_h + 2'd2 : f_h - 2'd2;
      default: f_h <= f_h;
    endcase
    if (f_move == 2'd2) f_missed <= f_missed + 1'b1;
    f_misread <= f_misread + {3'd0, f_flip[0]} + {3'd0, f_flip[1]};
  end
  always @(*) begin
    assume (sync_a == f_q[1] && sync_b == (f_q[1] == f_q[0]));
    assume (head1 == (F_S[f_p] ^ f_flip[0]) && head2 == (F_S[f_p2] ^ f_flip[1]));
    assume (f_missed <= `F_MISSED && f_misread <= `F_MISREADS);
  end
  // The pins of clock k are sampled by the edge that ends it; the outputs show that
  // sample 6 + FILTER edges later, on clock k + 7 + FILTER.
  localparam integer F_LATENCY = 7 + FILTER;
  reg [N+1:0] f_h_d [0:F_LATENCY-1];
  integer f_d;
  always @(posedge clk) begin
    f_h_d[0] <= f_h;
    for (f_d = 1; f_d < F_LATENCY; f_d = f_d + 1) f_h_d[f_d] <= f_h_d[f_d - 1];
  end
  always @(*) begin
    if (f_past_valid && f_since_rst >= F_LATENCY && pos_valid) begin
      assert (pos_hyb == f_h_d[F_LATENCY - 1]);
    end
  end
  // The first lock after a missed state while acquiring (the windows keep the readings
  // that are right either way): within the disc task's depth (task disc_cover, 30
  // clocks).
  reg f_was_valid = 1'b0;
  reg f_missed_acquiring = 1'b0;
  always @(posedge clk) begin
    if (pos_valid) f_was_valid <= 1'b1;
    if (f_move == 2'd2 && !f_was_valid && f_since_rst >= 4'd4) f_missed_acquiring <= 1'b1;
    if (f_past_valid && !rst) cover (pos_valid && f_missed_acquiring);
  end
`endif
`ifndef F_DISC
  // From the pins: the first lock on both heads, on one head, the hypotheses of a
  // missed state, a misread survived (cover traces: the whole reader at work).
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (mode == 3'd1);
      cover (mode == 3'd2);
      cover (mode == 3'd3);
      cover (dual);
      // A misread counted, and the position kept in normal mode.
      cover (mode == 3'd1 && (track1_errors != 0 || track2_errors != 0));
    end
  end
`endif
`endif

endmodule

`resetall
