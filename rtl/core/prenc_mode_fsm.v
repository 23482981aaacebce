// SPDX-License-Identifier: Apache-2.0
// prenc_mode_fsm: the judge of the offset; the modes and the only source of pos_valid.
//
// The position is the slot count plus an offset; this machine decides the offset and
// whether it stands. It sees, one clock after the track words (the J1 registers of
// prenc_core), each strobe with both tracks' offsets (converted slot - window base),
// their lock evidence (span, settled), their law-mode comparisons, and each illegal
// quadrature transition.
//   0 ACQUIRE / 4 INCREMENTAL (no offset, pos_valid 0): both tracks full and settled
//     on one offset with spans >= LOCK_BOTH - 1 (N + LOCK_BOTH - 1 distinct slots
//     each), or one track full and settled with span >= LOCK_ONE - 1 while the other
//     is not settled on another offset, lock: that
//     offset; those tracks turn to law mode. A head that is not quiet (a
//     disagreement in its last QUIET checks) needs LOCK_EXTRA slots more.
//     A track's offset counts only while it is steady (the same as on the clock
//     before: prenc_track_word), and a full, settled track whose offset just moved
//     blocks any lock on that clock: so an offset that lags the words by one clock
//     (prenc_core with CONV_REG = 1) gives the same decisions.
//   1 NORMAL, 2 REDUCED_1, 3 REDUCED_2 (pos_valid 1): which law-mode tracks support
//     the offset (both, track 1 only, track 2 only). A raw track whose window converts
//     to the offset rejoins. No track left: the offset is dropped (INCREMENTAL).
//   dual (mode 4, pos_valid 0): an illegal transition while locked with both tracks
//     supporting. The count took the two steps in the last direction; the other
//     hypothesis is one slot the other way. A reading at a slot not yet visited since
//     the transition, where the two predict different bits, is a vote. A hypothesis
//     wins with DUAL_VOTES votes, one at least from each head, and none for the other.
//     The count's way: back to the modes. The other way: the offset moves one slot and
//     the tracks realign. Votes both ways, a track losing support, a second illegal
//     transition or DUAL_SPAN slots without a decision: drop. With one track
//     supporting, an illegal transition drops the offset at once.
// Timing: what does not depend on this clock's decision is registered a clock ahead
// from the `*_ahead` inputs (the J1 input: the track words' outputs): each track's
// span against the lock depths, full and settled, the votes, whether the slot is
// fresh, and the slot relative to the transition (its subtraction two clocks ahead,
// from slot_ahead2). The decisions equal those on the J1 values (same model).
// The decisions are written out once for each value of dual_reg, which chooses last,
// and the offsets' comparisons choose after it: the comparisons reach only the
// no-hypotheses case (g_case[0]) and the votes only the other.
// The arithmetic behind LOCK_BOTH / LOCK_ONE: docs/architecture.md.
// Model: prenc.mode_fsm.ModeFsm (decisions registered; flush, law_on and realign are
// one-clock pulses to the track words).
//
// Latency: the judge's decisions are registered: pos_valid, the offset and the mode
// change one clock after the track words' registered evidence they follow (the core's 6
// + FILTER clocks from the pins in all).
//
// Parameters
//   N            offset width, 2..24
//   LOCK_BOTH    two-track lock: N + LOCK_BOTH - 1 slots per track, 1..32
//                (default 2 for N >= 8, 3 below)
//   LOCK_ONE     one-track lock: N + LOCK_ONE - 1 slots, 2..64
//                (default N + 2 for N >= 8, N + 5 below)
//   LOCK_EXTRA   slots more per track when a head is not quiet, 0..16 (default 3)
//   DUAL_VOTES   votes that decide between two hypotheses, 2..7
//   DUAL_SPAN    slots of travel a decision may take, 1..2^(N-1)-1 and <= 63
//   HYPOTHESES   1: an illegal transition opens the two hypotheses (above); 0: it drops a
//                held offset at once, and the hypothesis logic is left out (about a fifth
//                of the core: for a sync track that never misses a state)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_mode_fsm #(
  parameter integer N          = 10,
  parameter integer LOCK_BOTH  = (N < 8) ? 3 : 2,
  parameter integer LOCK_ONE   = (N < 8) ? N + 5 : N + 2,
  parameter integer LOCK_EXTRA = 3,
  parameter integer DUAL_VOTES = 3,
  parameter integer DUAL_SPAN  = 12,
  parameter integer HYPOTHESES = 1
) (
  input  wire         clk,
  input  wire         rst,
  // J1: one strobe or illegal transition, both tracks
  input  wire         strobe,
  input  wire         illegal,
  input  wire         illegal_cw,
  input  wire [N-1:0] slot,
  input  wire [1:0]   slot_ahead,   // the next clock's slot (the J1 input), two LSBs
  input  wire [N-1:0] slot_ahead2,  // the slot after it (the track words' input)
  input  wire [1:0]   full_ahead,     // lock evidence of the next event (the J1 input)
  input  wire [1:0]   steady_ahead,   // each track's offset the same as on the clock before
  input  wire [N-1:0] off1,
  input  wire [N-1:0] off2,
  input  wire [5:0]   span1_ahead,
  input  wire [5:0]   span2_ahead,
  input  wire [1:0]   settled_ahead,
  input  wire [1:0]   quiet_ahead,
  // the tracks' law-mode comparisons of the next event (the J1 input): the judge
  // registers its votes from them, one clock ahead
  input  wire [1:0]   checked_ahead,
  input  wire [1:0]   mismatch_ahead,
  input  wire [1:0]   mismatch_lo_ahead,
  input  wire [1:0]   mismatch_hi_ahead,
  // the tracks now
  input  wire [1:0]   supported,
  input  wire [1:0]   law,
  output wire [2:0]   mode,
  output wire         pos_valid,
  output wire         dual,
  output wire         dual_cw,
  output wire [N-1:0] offset,
  output wire [1:0]   flush,
  output wire [1:0]   law_on,
  output wire         realign_up,
  output wire         realign_down
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_mode_fsm_parameter_N_out_of_range_2_to_24 u_stop ();
    end
    if (LOCK_BOTH < 1 || LOCK_BOTH > 32) begin : g_bad_lock_both
      initial $display("ERROR: %m: parameter LOCK_BOTH = %0d is out of range 1..32", LOCK_BOTH);
      prenc_mode_fsm_parameter_LOCK_BOTH_out_of_range_1_to_32 u_stop ();
    end
    if (LOCK_ONE < 2 || LOCK_ONE > 64) begin : g_bad_lock_one
      initial $display("ERROR: %m: parameter LOCK_ONE = %0d is out of range 2..64", LOCK_ONE);
      prenc_mode_fsm_parameter_LOCK_ONE_out_of_range_2_to_64 u_stop ();
    end
    if (LOCK_EXTRA < 0 || LOCK_EXTRA > 16) begin : g_bad_lock_extra
      initial $display("ERROR: %m: parameter LOCK_EXTRA = %0d is out of range 0..16", LOCK_EXTRA);
      prenc_mode_fsm_parameter_LOCK_EXTRA_out_of_range_0_to_16 u_stop ();
    end
    if (DUAL_VOTES < 2 || DUAL_VOTES > 7) begin : g_bad_dual_votes
      initial $display("ERROR: %m: parameter DUAL_VOTES = %0d is out of range 2..7", DUAL_VOTES);
      prenc_mode_fsm_parameter_DUAL_VOTES_out_of_range_2_to_7 u_stop ();
    end
    if (DUAL_SPAN < 1 || DUAL_SPAN > 63 ||
        (N < 8 && DUAL_SPAN >= (1 << (N - 1)))) begin : g_bad_dual_span
      initial $display("ERROR: %m: parameter DUAL_SPAN = %0d: need 1..63 and < 2^(N-1)", DUAL_SPAN);
      prenc_mode_fsm_parameter_DUAL_SPAN_out_of_range u_stop ();
    end
    if (HYPOTHESES != 0 && HYPOTHESES != 1) begin : g_bad_hypotheses
      initial $display("ERROR: %m: parameter HYPOTHESES = %0d must be 0 or 1", HYPOTHESES);
      prenc_mode_fsm_parameter_HYPOTHESES_must_be_0_or_1 u_stop ();
    end
  endgenerate

  localparam [2:0] ACQUIRE     = 3'd0;
  localparam [2:0] NORMAL      = 3'd1;
  localparam [2:0] REDUCED_1   = 3'd2;
  localparam [2:0] REDUCED_2   = 3'd3;
  localparam [2:0] INCREMENTAL = 3'd4;
  localparam [31:0] NEED_BOTH32 = LOCK_BOTH - 1;
  localparam [31:0] NEED_ONE32  = LOCK_ONE - 1;
  localparam [31:0] SPAN32      = DUAL_SPAN;
  localparam [31:0] DEEP_BOTH32 = LOCK_BOTH - 1 + LOCK_EXTRA;
  localparam [31:0] DEEP_ONE32  = LOCK_ONE - 1 + LOCK_EXTRA;
  localparam [5:0]  NEED_BOTH   = NEED_BOTH32[5:0];
  localparam [5:0]  NEED_ONE    = NEED_ONE32[5:0];
  localparam [5:0]  DEEP_BOTH   = DEEP_BOTH32[5:0];
  localparam [5:0]  DEEP_ONE    = DEEP_ONE32[5:0];

  // A span has reached a depth.
  function reaches(input [5:0] span, input [5:0] depth);
    reaches = (span >= depth);
  endfunction
  // Slots relative to the transition, signed, wide enough for +-(DUAL_SPAN + 1).
  localparam integer RW = 7;
  localparam signed [RW-1:0] SPAN_P = SPAN32[RW-1:0];
  localparam signed [RW-1:0] SPAN_M = -SPAN32[RW-1:0];

  reg [2:0]          mode_reg;
  reg [N-1:0]        offset_reg;
  reg                dual_reg;
  reg                dual_cw_reg;
  reg [N-1:0]        anchor_reg;
  reg signed [RW-1:0] lo_reg;
  reg signed [RW-1:0] hi_reg;
  reg [DUAL_VOTES-1:0] votes_keep_reg;   // votes as a thermometer code: bit k = more than k
  reg [DUAL_VOTES-1:0] votes_other_reg;
  reg [3:0]          voted_reg;     // {other by 2, other by 1, keep by 2, keep by 1}
  reg [1:0]          flush_reg;
  reg [1:0]          law_on_reg;
  reg [1:0]          realign_reg;  // {up, down}

  wire valid_now = (mode_reg == NORMAL) | (mode_reg == REDUCED_1) | (mode_reg == REDUCED_2);
  // What the tracks will be once last clock's pulses land.
  wire [1:0] sup    = (supported & ~flush_reg) | law_on_reg;
  wire [1:0] lawish = (law & ~flush_reg) | law_on_reg;
  // Lock evidence, in parallel with the state logic.
  // The span comparisons are registered one clock ahead, from the J1 input.
  // Each span against the constant depths, then the head's quiet chooses (a comparison
  // with a chosen depth is an adder's carry chain; with a constant, plain logic).
  // (A function: with LOCK_BOTH or LOCK_ONE = 1 a depth is 0, always reached, which
  // lint would flag as a constant comparison.)
  wire [1:0] ge_need_both = {reaches(span2_ahead, NEED_BOTH), reaches(span1_ahead, NEED_BOTH)};
  wire [1:0] ge_deep_both = {reaches(span2_ahead, DEEP_BOTH), reaches(span1_ahead, DEEP_BOTH)};
  wire [1:0] ge_need_one  = {reaches(span2_ahead, NEED_ONE), reaches(span1_ahead, NEED_ONE)};
  wire [1:0] ge_deep_one  = {reaches(span2_ahead, DEEP_ONE), reaches(span1_ahead, DEEP_ONE)};
  reg  [1:0] full;        // full and steady: its offset may be read
  reg  [1:0] ready;       // full, steady and settled
  reg        blocked;     // a full, settled track's offset just moved: no lock now
  reg  [1:0] span_both;   // span >= the two-track need
  reg  [1:0] span_one;    // span >= the one-track need
  always @(posedge clk) begin
    full      <= full_ahead & steady_ahead;
    ready     <= full_ahead & settled_ahead & steady_ahead;
    blocked   <= |(full_ahead & settled_ahead & ~steady_ahead);
    span_both <= (&quiet_ahead) ? ge_need_both : ge_deep_both;
    span_one  <= (quiet_ahead & ge_need_one) | (~quiet_ahead & ge_deep_one);
    if (rst) begin
      full      <= 2'b00;
      ready     <= 2'b00;
      blocked   <= 1'b0;
      span_both <= 2'b00;
      span_one  <= 2'b00;
    end
  end
  // Whether a lock is due if the two offsets agree, and if they do not, from registers
  // in parallel with the offsets' comparison, which then only chooses between them.
  wire [1:0] alone      = ready & span_one;  // one head's own evidence
  wire       both_deep  = (&ready) & (&span_both);
  wire       lock_agree = both_deep | (|alone);
  wire       lock_alone = (alone[0] & ~ready[1]) | (alone[1] & ~ready[0]);
  // Both heads on one offset, or one head alone unless the other is settled on another.
  // Kept as one net: the decisions below take it as their last input (without the
  // attribute Yosys's ABC merged it into them, two LUT levels deeper on iCE40).
  // In pairs of bits, kept (ABC otherwise chains the comparison a level deeper).
  localparam integer NP = (N + 1) / 2;
  wire [2*NP-1:0] off1_p = {{(2 * NP - N){1'b0}}, off1};
  wire [2*NP-1:0] off2_p = {{(2 * NP - N){1'b0}}, off2};
  (* keep *) wire [NP-1:0] agree_pair;
  genvar gp;
  generate
    for (gp = 0; gp < NP; gp = gp + 1) begin : g_agree_pair
      assign agree_pair[gp] = (off1_p[2*gp+1:2*gp] == off2_p[2*gp+1:2*gp]);
    end
  endgenerate
  (* keep *) wire agree12;
  assign agree12 = &agree_pair;
  wire       on1     = (off1 == offset_reg);
  wire       on2     = (off2 == offset_reg);
  // Dual: where this strobe is, relative to the transition. The subtraction runs two
  // clocks ahead, on the slot entering the track words (slot_ahead2) and the anchor as
  // this clock leaves it, and is registered: rel_d = slot_ahead - anchor_reg, from a
  // register. In dual it is the next event's place; otherwise a transition judged now
  // anchors the next event, which is then at most one slot away (the count moves one
  // slot per clock at most): the step between the two slots (rel_step).
  wire [N-1:0] anchor_next_w = dual_reg ? anchor_reg : slot;
  wire [N-1:0] rel_n = slot_ahead2 - anchor_next_w;
  wire signed [RW-1:0] rel_n_w;
  wire         far_n;
  generate
    if (N > RW) begin : g_rel_wide
      wire [N-RW:0] top = rel_n[N-1:RW-1];
      wire signed [RW-1:0] rel_w = rel_n[RW-1:0];
      assign far_n   = ~((&top) | ~(|top)) | (rel_w > SPAN_P) | (rel_w < SPAN_M);
      assign rel_n_w = rel_n[RW-1:0];
    end else begin : g_rel_narrow
      wire signed [RW-1:0] rel_x = {{(RW - N){rel_n[N-1]}}, rel_n};
      assign far_n   = (rel_x > SPAN_P) | (rel_x < SPAN_M);
      assign rel_n_w = rel_x;
    end
  endgenerate
  reg signed [RW-1:0] rel_d;  // slot_ahead - anchor_reg
  reg                 far_d;
  reg signed [RW-1:0] rel;    // this event's place
  reg                 far;
  wire [1:0] step2 = slot_ahead - slot[1:0];  // 0, 1 or 3 (-1)
  wire signed [RW-1:0] rel_step = (step2 == 2'd1) ? 1 : (step2 == 2'd3) ? -1 : 0;
  always @(posedge clk) begin
    rel_d <= rel_n_w;
    far_d <= far_n;
    rel   <= dual_reg ? rel_d : rel_step;
    far   <= dual_reg & far_d;  // DUAL_SPAN >= 1
    if (rst) begin
      rel_d <= {RW{1'b0}};
      far_d <= 1'b0;
      rel   <= {RW{1'b0}};
      far   <= 1'b0;
    end
  end
  // Fresh (outside the slots visited since the transition), also one clock ahead:
  // against the interval as this clock's event leaves it.
  // The four comparisons kept as nets, each its own carry chain (merged, ABC made
  // them ten LUT levels deep).
  (* keep *) wire widen;
  assign widen = ~illegal & strobe & dual_reg & ~far & fresh;
  (* keep *) wire below_reg;
  assign below_reg = (rel_d < lo_reg);
  (* keep *) wire above_reg;
  assign above_reg = (rel_d > hi_reg);
  // In dual the next event's place less this one's is the count's step between them
  // (rel_d - rel = slot_ahead - slot: one slot at most), so its sign is read from the
  // two slots' low bits, not from two comparisons of rel_d with rel. (Where rel_d
  // leaves RW bits, the next event is far, and fresh and the interval go unread.)
  wire not_above = (step2 != 2'd3);  // rel_d >= rel
  wire not_below = (step2 != 2'd1);  // rel_d <= rel
  wire below  = below_reg & ~(widen & not_above);  // used in dual only
  wire above  = above_reg & ~(widen & not_below);
  reg  fresh;
  reg  below_lo;  // rel < lo_reg (this event below the interval), registered with it
  reg  above_hi;  // rel > hi_reg
  always @(posedge clk) begin
    fresh    <= ~dual_reg | below | above;
    // Outside dual the interval restarts empty (lo 1, hi 0) and rel is the step.
    below_lo <= dual_reg ? below : (step2 != 2'd1);
    above_hi <= dual_reg ? above : (step2 == 2'd1);
    if (rst) begin
      fresh    <= 1'b0;
      below_lo <= 1'b1;
      above_hi <= 1'b0;
    end
  end
  // Votes, registered one clock ahead: a reading where the two hypotheses predict
  // different bits votes for the one it matches. The way of a transition judged now
  // is forwarded.
  wire       dual_cw_ahead = dual_reg ? dual_cw_reg : illegal_cw;
  wire [1:0] alt_ahead     = dual_cw_ahead ? mismatch_lo_ahead : mismatch_hi_ahead;
  wire [1:0] vote_ahead    = checked_ahead & (mismatch_ahead ^ alt_ahead);
  reg  [1:0] vote_keep;
  reg  [1:0] vote_other;
  always @(posedge clk) begin
    vote_keep  <= vote_ahead & ~mismatch_ahead;
    vote_other <= vote_ahead & mismatch_ahead;
    if (rst) begin
      vote_keep  <= 2'b00;
      vote_other <= 2'b00;
    end
  end
  // Adding one or two votes shifts ones into the thermometer (saturating at DUAL_VOTES).
  wire [DUAL_VOTES:0]   keep_ext  = {votes_keep_reg[DUAL_VOTES-2:0], 2'b11};
  wire [DUAL_VOTES:0]   other_ext = {votes_other_reg[DUAL_VOTES-2:0], 2'b11};
  wire [DUAL_VOTES-1:0] keep_new  = (&vote_keep) ? keep_ext[DUAL_VOTES-1:0] :
                                    (|vote_keep) ? keep_ext[DUAL_VOTES:1] : votes_keep_reg;
  wire [DUAL_VOTES-1:0] other_new = (&vote_other) ? other_ext[DUAL_VOTES-1:0] :
                                    (|vote_other) ? other_ext[DUAL_VOTES:1] : votes_other_reg;
  wire [3:0] voted_new  = voted_reg | {vote_other, vote_keep};

  reg                 dual_cw_next;
  reg [N-1:0]         anchor_next;
  reg signed [RW-1:0] lo_next;
  reg signed [RW-1:0] hi_next;
  reg [DUAL_VOTES-1:0] votes_keep_next;
  reg [DUAL_VOTES-1:0] votes_other_next;
  reg [3:0]           voted_next;
  // A lock on a strobe while no offset is held: which tracks, and the mode it gives,
  // from registers for either outcome of the offsets' comparison, which then chooses.
  // Where the offsets agree either is the lock's; where not, the one head that locks.
  wire       one1_apart    = alone[0] & ~ready[1];
  wire       lock_off2     = ~alone[0] & alone[1];
  wire [N-1:0] lock_offset = lock_off2 ? off2 : off1;
  // A raw track whose full word converts to the held offset rejoins (law mode).
  wire [1:0] rejoin      = {full[1] & ~lawish[1] & on2, full[0] & ~lawish[0] & on1};

  // The hypothesis state: outside dual held at its starting values (the event's way
  // and slot, nothing visited, no votes), ready for a transition judged now; in dual a
  // fresh reading (widen) widens the interval and adds its votes.
  always @* begin
    dual_cw_next     = dual_cw_ahead;
    anchor_next      = anchor_next_w;
    lo_next          = ~dual_reg ? 1 : (widen & below_lo) ? rel : lo_reg;
    hi_next          = ~dual_reg ? 0 : (widen & above_hi) ? rel : hi_reg;
    votes_keep_next  = ~dual_reg ? {DUAL_VOTES{1'b0}} : widen ? keep_new : votes_keep_reg;
    votes_other_next = ~dual_reg ? {DUAL_VOTES{1'b0}} : widen ? other_new : votes_other_reg;
    voted_next       = ~dual_reg ? 4'd0 : widen ? voted_new : voted_reg;
  end

  // The decisions, written once for each value of dual_reg (g_case[0]: no hypotheses
  // open, g_case[1]: two open), and dual_reg chooses last: the offsets' comparisons
  // (agree12, on1, on2) reach only the first, whose logic is that of HYPOTHESES = 0
  // with `enter`, and the votes only the second.
  wire [2:0] mode_ca  [0:1];  // per case: the mode if the offsets agree / are apart
  wire [2:0] mode_cp  [0:1];
  wire [1:0] law_ca   [0:1];
  wire [1:0] law_cp   [0:1];
  wire       dual_n_c [0:1];
  wire       flush_c  [0:1];
  wire       en_ca    [0:1];  // the offset loads (if they agree / are apart)
  wire       en_cp    [0:1];
  wire [1:0] realign_c[0:1];
  genvar gd;
  generate
    for (gd = 0; gd < 2; gd = gd + 1) begin : g_case
      wire       d_now    = (gd == 1);
      wire       locked_c = valid_now | d_now;
      wire       lock_try = ~illegal & strobe & ~locked_c & ~blocked;
      wire [1:0] law_on_agree = ~lock_try ? 2'b00 : both_deep ? 2'b11 :
                                alone[0] ? 2'b01 : alone[1] ? 2'b10 : 2'b00;
      wire [1:0] law_on_apart = ~lock_try ? 2'b00 : one1_apart ? 2'b01 :
                                (alone[1] & ~ready[0]) ? 2'b10 : 2'b00;
      wire [2:0] mode_agree   = ~(lock_try & lock_agree) ? mode_reg : both_deep ? NORMAL :
                                alone[0] ? REDUCED_1 : REDUCED_2;
      wire [2:0] mode_apart   = ~(lock_try & lock_alone) ? mode_reg :
                                one1_apart ? REDUCED_1 : REDUCED_2;
      // An illegal transition that opens the two hypotheses (HYPOTHESES = 0: none, and
      // dual_reg stays 0, so synthesis drops all that follows from it).
      wire       enter = (HYPOTHESES == 1) & illegal & valid_now & ~d_now & (sup == 2'b11);
      reg  [1:0] law_on_held;
      reg  [1:0] realign_here;  // this case's realignment (realign_c)
      reg        drop;  // the offset is dropped (flush, INCREMENTAL)
      reg        won;   // a hypothesis won: the modes resume from support
      always @* begin
        law_on_held  = 2'b00;
        realign_here = 2'b00;
        drop         = 1'b0;
        won          = 1'b0;
        if (illegal) begin
          // enter opens the two hypotheses; otherwise a held offset drops.
          drop = locked_c & ~enter;
        end else if (strobe && !locked_c) begin
          // A lock (lock_try, above), chosen by the offsets' comparison.
        end else if (strobe && !d_now) begin
          law_on_held = rejoin;
        end else if (strobe) begin
          if (far) begin
            drop = 1'b1;
          end else if (fresh) begin
            if (keep_new[0] && other_new[0]) begin
              drop = 1'b1;
            end else if (keep_new[DUAL_VOTES-1] && voted_new[0] && voted_new[1]) begin
              won = 1'b1;
            end else if (other_new[DUAL_VOTES-1] && voted_new[2] && voted_new[3]) begin
              // The other way: the count is one slot off; the offset takes it.
              won          = 1'b1;
              realign_here = dual_cw_reg ? 2'b01 : 2'b10;
            end
          end
        end
      end
      // Modes from support, every clock, while the offset stands: the support of this
      // clock with the tracks that rejoin now (a lock or a won hypothesis adds none).
      wire [1:0] support_now = sup | ((~illegal & strobe & locked_c & ~d_now) ? rejoin : 2'b00);
      wire [2:0] s_mode      = (support_now == 2'b11) ? NORMAL :
                               (support_now == 2'b01) ? REDUCED_1 :
                               (support_now == 2'b10) ? REDUCED_2 : INCREMENTAL;
      // Two hypotheses stay open (or open now) while both tracks support the offset.
      wire       dual_keep = (illegal & enter) | (d_now & ~won);
      // (A lock needs no offset held, resume one held: never both.)
      wire       resume    = ~drop & ~dual_keep & (valid_now | won);
      wire [2:0] mode_held = (drop | dual_keep) ? INCREMENTAL : resume ? s_mode : mode_reg;
      assign mode_ca[gd]   = locked_c ? mode_held : mode_agree;
      assign mode_cp[gd]   = locked_c ? mode_held : mode_apart;
      assign law_ca[gd]    = locked_c ? law_on_held : law_on_agree;
      assign law_cp[gd]    = locked_c ? law_on_held : law_on_apart;
      assign dual_n_c[gd]  = (HYPOTHESES == 1) & dual_keep & ~drop & (sup == 2'b11);
      assign flush_c[gd]   = drop | (dual_keep & (sup != 2'b11)) |
                             (resume & (support_now == 2'b00));
      assign en_ca[gd]     = (lock_try & lock_agree) | (realign_here != 2'b00);
      assign en_cp[gd]     = (lock_try & lock_alone) | (realign_here != 2'b00);
      assign realign_c[gd] = realign_here;
    end
  endgenerate
  // For either outcome of the offsets' comparison, kept as nets so that it is the
  // last input (one LUT level) of the mode, law_on and the offset's enable.
  (* keep *) wire [2:0] mode_if_agree;
  assign mode_if_agree = dual_reg ? mode_ca[1] : mode_ca[0];
  (* keep *) wire [2:0] mode_if_apart;
  assign mode_if_apart = dual_reg ? mode_cp[1] : mode_cp[0];
  (* keep *) wire [1:0] law_on_if_agree;
  assign law_on_if_agree = dual_reg ? law_ca[1] : law_ca[0];
  (* keep *) wire [1:0] law_on_if_apart;
  assign law_on_if_apart = dual_reg ? law_cp[1] : law_cp[0];
  wire [2:0] mode_next    = agree12 ? mode_if_agree : mode_if_apart;
  wire [1:0] law_on_next  = agree12 ? law_on_if_agree : law_on_if_apart;
  (* keep *) wire offset_en_if_agree;
  assign offset_en_if_agree = dual_reg ? en_ca[1] : en_ca[0];
  (* keep *) wire offset_en_if_apart;
  assign offset_en_if_apart = dual_reg ? en_cp[1] : en_cp[0];
  wire       offset_en    = agree12 ? offset_en_if_agree : offset_en_if_apart;
  wire       dual_next    = dual_reg ? dual_n_c[1] : dual_n_c[0];
  wire [1:0] realign_next = dual_reg ? realign_c[1] : realign_c[0];
  // The offset: a lock's (outside dual), or the other hypothesis's when it wins (in dual).
  wire [N-1:0] offset_load = dual_reg ? offset_reg + {{(N - 1){dual_cw_reg}}, 1'b1} :  // -1 CW
                                        lock_offset;                                   // +1 CCW
  wire       flush_all    = dual_reg ? flush_c[1] : flush_c[0];
  wire [1:0] flush_next  = {flush_all, flush_all};

  always @(posedge clk) begin
    mode_reg        <= mode_next;
    if (offset_en) offset_reg <= offset_load;
    dual_reg        <= dual_next;
    dual_cw_reg     <= dual_cw_next;
    anchor_reg      <= anchor_next;
    lo_reg          <= lo_next;
    hi_reg          <= hi_next;
    votes_keep_reg  <= votes_keep_next;
    votes_other_reg <= votes_other_next;
    voted_reg       <= voted_next;
    flush_reg       <= flush_next;
    law_on_reg      <= law_on_next;
    realign_reg     <= realign_next;
    if (rst) begin
      mode_reg        <= ACQUIRE;
      offset_reg      <= {N{1'b0}};
      dual_reg        <= 1'b0;
      dual_cw_reg     <= 1'b0;
      anchor_reg      <= {N{1'b0}};
      lo_reg          <= 1;
      hi_reg          <= 0;
      votes_keep_reg  <= {DUAL_VOTES{1'b0}};
      votes_other_reg <= {DUAL_VOTES{1'b0}};
      voted_reg       <= 4'd0;
      flush_reg       <= 2'b00;
      law_on_reg      <= 2'b00;
      realign_reg     <= 2'b00;
    end
  end

  assign mode         = mode_reg;
  assign pos_valid    = valid_now & ~dual_reg;
  assign dual         = dual_reg;
  assign dual_cw      = dual_cw_reg;
  assign offset       = offset_reg;
  assign flush        = flush_reg;
  assign law_on       = law_on_reg;
  assign realign_up   = realign_reg[1];
  assign realign_down = realign_reg[0];

`ifdef FORMAL
  // Properties (formal/prenc_mode_fsm.sby), on the registers after each clock. The
  // evidence is restated from the inputs, one clock before the decision as the judge
  // registers it (the `*_ahead` inputs), not read from the judge's own registers.
  reg f_past_valid = 1'b0;
  reg f_rst_prev;
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_rst_prev   <= rst;
  end
  initial assume (rst);
  // The core's inputs are consistent: the count moves at most one slot a clock, and
  // the *_ahead slots are the next clocks' (the pipeline of prenc_core).
  reg [N-1:0] f_ahead2_prev;
  reg [N-1:0] f_ahead2_prev2;
  reg         f_past_valid2 = 1'b0;
  always @(posedge clk) begin
    f_ahead2_prev  <= slot_ahead2;
    f_ahead2_prev2 <= f_ahead2_prev;
    f_past_valid2  <= f_past_valid;
  end
  always @(*) begin
    if (f_past_valid) assume (slot_ahead == f_ahead2_prev[1:0]);
    if (f_past_valid2) assume (slot == f_ahead2_prev2);
    if (f_past_valid) begin
      assume (slot_ahead2 == f_ahead2_prev || slot_ahead2 == f_ahead2_prev + 1'b1 ||
              slot_ahead2 == f_ahead2_prev - 1'b1);
    end
    assume (!(strobe && illegal));  // one event a clock
  end
  // Lock evidence of this clock's event, from the last clock's *_ahead inputs.
  localparam [6:0] F_BOTH = LOCK_BOTH - 1;
  localparam [6:0] F_ONE  = LOCK_ONE - 1;
  localparam [6:0] F_X    = LOCK_EXTRA;
  reg [1:0] f_ready;     // full, steady and settled
  reg       f_blocked;   // a full, settled track that is not steady
  reg [1:0] f_span_both;
  reg [1:0] f_span_one;
  reg [1:0] f_vote_keep;   // a reading that matches the count's hypothesis, not the other
  reg [1:0] f_vote_other;  // the mirror
  wire [1:0] f_alt = (dual ? dual_cw : illegal_cw) ? mismatch_lo_ahead : mismatch_hi_ahead;
  always @(posedge clk) begin
    f_ready        <= full_ahead & settled_ahead & steady_ahead;
    f_blocked      <= |(full_ahead & settled_ahead & ~steady_ahead);
    f_span_both[0] <= {1'b0, span1_ahead} >= F_BOTH + ((&quiet_ahead) ? 7'd0 : F_X);
    f_span_both[1] <= {1'b0, span2_ahead} >= F_BOTH + ((&quiet_ahead) ? 7'd0 : F_X);
    f_span_one[0]  <= {1'b0, span1_ahead} >= F_ONE + (quiet_ahead[0] ? 7'd0 : F_X);
    f_span_one[1]  <= {1'b0, span2_ahead} >= F_ONE + (quiet_ahead[1] ? 7'd0 : F_X);
    f_vote_keep    <= checked_ahead & ~mismatch_ahead & f_alt;
    f_vote_other   <= checked_ahead & mismatch_ahead & ~f_alt;
    if (rst) begin
      f_ready      <= 2'b00;
      f_blocked    <= 1'b0;
      f_span_both  <= 2'b00;
      f_span_one   <= 2'b00;
      f_vote_keep  <= 2'b00;
      f_vote_other <= 2'b00;
    end
  end
  wire f_both = !f_blocked && f_ready[0] && f_ready[1] && off1 == off2 && (&f_span_both);
  wire f_one1 = !f_blocked && f_ready[0] && f_span_one[0] && !(f_ready[1] && off1 != off2);
  wire f_one2 = !f_blocked && f_ready[1] && f_span_one[1] && !(f_ready[0] && off1 != off2);
  // Two open hypotheses, as documented: the slots read since the transition form an
  // interval around its slot (the count moves one slot a clock at most); a reading
  // outside it and within DUAL_SPAN slots is a vote where the hypotheses differ.
  reg        [N-1:0] f_anchor;
  reg signed [N-1:0] f_lo;  // slots read since the transition, relative to it
  reg signed [N-1:0] f_hi;  // (none yet: lo > hi)
  wire signed [N-1:0] f_rel = slot - f_anchor;
  wire f_far   = (f_rel > DUAL_SPAN) || (f_rel < -DUAL_SPAN);
  wire f_fresh = (f_rel < f_lo) || (f_rel > f_hi);
  wire f_counting = dual && strobe && !f_far && f_fresh;
  reg [2:0] f_keep_n;
  reg [2:0] f_other_n;
  reg [1:0] f_keep_heads;
  reg [1:0] f_other_heads;
  wire [2:0] f_keep_add  = {2'b00, f_vote_keep[0]} + {2'b00, f_vote_keep[1]};
  wire [2:0] f_other_add = {2'b00, f_vote_other[0]} + {2'b00, f_vote_other[1]};
  wire [3:0] f_keep_sum  = {1'b0, f_keep_n} + {1'b0, f_keep_add};
  wire [3:0] f_other_sum = {1'b0, f_other_n} + {1'b0, f_other_add};
  wire [2:0] f_keep_now  = !f_counting ? f_keep_n : f_keep_sum[3] ? 3'd7 : f_keep_sum[2:0];
  wire [2:0] f_other_now = !f_counting ? f_other_n : f_other_sum[3] ? 3'd7 : f_other_sum[2:0];
  wire [1:0] f_keep_heads_now  = f_keep_heads | (f_counting ? f_vote_keep : 2'b00);
  wire [1:0] f_other_heads_now = f_other_heads | (f_counting ? f_vote_other : 2'b00);
  always @(posedge clk) begin
    f_keep_n      <= dual ? f_keep_now : 3'd0;
    f_other_n     <= dual ? f_other_now : 3'd0;
    f_keep_heads  <= dual ? f_keep_heads_now : 2'b00;
    f_other_heads <= dual ? f_other_heads_now : 2'b00;
    if (!dual) begin
      f_anchor <= slot;
      f_lo     <= 1;
      f_hi     <= 0;
    end else if (f_counting) begin
      if (f_rel < f_lo) f_lo <= f_rel;
      if (f_rel > f_hi) f_hi <= f_rel;
    end
    if (rst) begin
      f_keep_n      <= 3'd0;
      f_other_n     <= 3'd0;
      f_keep_heads  <= 2'b00;
      f_other_heads <= 2'b00;
    end
  end
  // Last clock's state and decision inputs.
  reg         f_valid_prev;
  reg         f_dual_prev;
  reg         f_dual_cw_prev;
  reg         f_strobe_prev;
  reg         f_illegal_prev;
  reg         f_both_prev;
  reg         f_one1_prev;
  reg         f_one2_prev;
  reg [N-1:0] f_off1_prev;
  reg [N-1:0] f_off2_prev;
  reg [N-1:0] f_offset_prev;
  reg [2:0]   f_mode_prev;
  reg [1:0]   f_sup_prev;     // the tracks supporting, once last clock's pulses landed
  reg [2:0]   f_keep_prev;    // votes up to last clock's event, included
  reg [2:0]   f_other_prev;
  reg [1:0]   f_keep_heads_prev;
  reg [1:0]   f_other_heads_prev;
  reg         f_far_prev;
  reg         f_counting_prev;
  reg [1:0]   f_full_prev;    // the judge's view of full and steady (from the *_ahead)
  reg [1:0]   f_lawish_prev;  // the tracks in law mode, once last clock's pulses landed
  reg [1:0]   f_full;
  always @(posedge clk) begin
    f_full <= rst ? 2'b00 : full_ahead & steady_ahead;
  end
  always @(posedge clk) begin
    f_far_prev         <= f_far;
    f_counting_prev    <= f_counting;
    f_full_prev        <= f_full;
    f_lawish_prev      <= (law & ~flush) | law_on;
    f_valid_prev       <= pos_valid;
    f_dual_prev        <= dual;
    f_dual_cw_prev     <= dual_cw;
    f_strobe_prev      <= strobe;
    f_illegal_prev     <= illegal;
    f_both_prev        <= f_both;
    f_one1_prev        <= f_one1;
    f_one2_prev        <= f_one2;
    f_off1_prev        <= off1;
    f_off2_prev        <= off2;
    f_offset_prev      <= offset;
    f_mode_prev        <= mode;
    f_sup_prev         <= (supported & ~flush) | law_on;
    f_keep_prev        <= f_keep_now;
    f_other_prev       <= f_other_now;
    f_keep_heads_prev  <= f_keep_heads_now;
    f_other_heads_prev <= f_other_heads_now;
  end
  localparam [2:0] F_VOTES = DUAL_VOTES;
  always @(*) begin
    if (f_past_valid) begin
      assert (mode <= INCREMENTAL);
      assert (pos_valid == (mode == NORMAL || mode == REDUCED_1 || mode == REDUCED_2));
      if (dual) assert (mode == INCREMENTAL);
    end
    if (f_past_valid && f_rst_prev) assert (mode == ACQUIRE && !dual && flush == 2'b00);
    if (f_past_valid && !f_rst_prev) begin
      // While valid, the offset stands: the position moves only with the count.
      if (f_valid_prev && pos_valid) assert (offset == f_offset_prev);
      // Two hypotheses open: the offset stands and pos_valid is 0.
      if (f_dual_prev && dual) assert (offset == f_offset_prev && dual_cw == f_dual_cw_prev);
      // An illegal transition: pos_valid is 0 on the next clock; while valid with both
      // tracks supporting it opens two hypotheses, otherwise the offset is dropped.
      if (f_illegal_prev) assert (!pos_valid);
      if (f_illegal_prev && f_valid_prev) begin
        if (f_sup_prev == 2'b11 && HYPOTHESES == 1) assert (dual && offset == f_offset_prev);
        else assert (!dual && mode == INCREMENTAL && flush == 2'b11);
      end
      // pos_valid rises only on the documented evidence.
      if (pos_valid && !f_valid_prev && !f_dual_prev) begin
        // A lock from acquiring or incremental: this strobe's tracks, with the lock
        // depth and agreement, give the offset, and those tracks turn to law mode.
        assert (f_strobe_prev);
        assert ((f_both_prev && offset == f_off1_prev && law_on == 2'b11 && mode == NORMAL) ||
                (!f_both_prev && f_one1_prev && offset == f_off1_prev && law_on == 2'b01 &&
                 mode == REDUCED_1) ||
                (!f_both_prev && !f_one1_prev && f_one2_prev && offset == f_off2_prev &&
                 law_on == 2'b10 && mode == REDUCED_2));
      end
      // And it rises on that evidence, on the strobe that brings it: no lock is held
      // back (the availability half of the promise).
      if (!f_valid_prev && !f_dual_prev && f_strobe_prev && !f_illegal_prev &&
          (f_both_prev || f_one1_prev || f_one2_prev)) begin
        assert (pos_valid);
      end
      if (pos_valid && f_dual_prev) begin
        // Two hypotheses decided: DUAL_VOTES readings at least for the winner, one
        // from each head at least; the count's way keeps the offset, the other way
        // moves it one slot and realigns the tracks.
        assert (f_strobe_prev);
        if (offset == f_offset_prev) begin
          assert (f_keep_prev >= F_VOTES && f_keep_heads_prev == 2'b11);
          assert (!realign_up && !realign_down);
        end else begin
          assert (f_other_prev >= F_VOTES && f_other_heads_prev == 2'b11);
          assert (offset == (f_dual_cw_prev ? f_offset_prev - 1'b1 : f_offset_prev + 1'b1));
          assert (realign_up == !f_dual_cw_prev && realign_down == f_dual_cw_prev);
        end
      end
      // Two hypotheses: a second illegal transition, a reading beyond DUAL_SPAN slots,
      // votes both ways or a track losing support drop the offset; DUAL_VOTES votes
      // from both heads and none the other way decide; otherwise both stay open.
      if (f_dual_prev) begin
        if (f_illegal_prev || (f_strobe_prev && f_far_prev) ||
            (f_counting_prev && f_keep_prev != 3'd0 && f_other_prev != 3'd0)) begin
          assert (!dual && mode == INCREMENTAL && flush == 2'b11);
        end else if (f_counting_prev && f_keep_prev >= F_VOTES && f_keep_heads_prev == 2'b11) begin
          assert (!dual && offset == f_offset_prev && (pos_valid || flush == 2'b11));
        end else if (f_counting_prev && f_other_prev >= F_VOTES &&
                     f_other_heads_prev == 2'b11) begin
          assert (!dual && (pos_valid || flush == 2'b11));
          assert (offset == (f_dual_cw_prev ? f_offset_prev - 1'b1 : f_offset_prev + 1'b1));
        end else if (f_sup_prev == 2'b11) begin
          assert (dual);
        end else begin
          assert (!dual && mode == INCREMENTAL && flush == 2'b11);
        end
      end
      // Return to normal: while valid, a track in raw mode whose full, steady window
      // converts to the offset rejoins (turns to law mode) on that strobe; no other does.
      if (f_valid_prev && f_strobe_prev) begin
        assert (law_on == (f_full_prev & ~f_lawish_prev &
                           {f_off2_prev == f_offset_prev, f_off1_prev == f_offset_prev}));
      end
      // No track supporting: the offset is dropped.
      if (f_valid_prev && f_sup_prev == 2'b00 && law_on == 2'b00) assert (!pos_valid);
      // A valid mode names the tracks that support the offset.
      if (f_valid_prev && pos_valid && !f_strobe_prev) begin
        assert (mode == ((f_sup_prev == 2'b11) ? NORMAL :
                         (f_sup_prev == 2'b01) ? REDUCED_1 : REDUCED_2));
      end
    end
  end
  // Helper invariants for the induction: the judge's vote record is within the
  // property's count (the judge counts only fresh readings).
  always @(*) begin
    if (f_past_valid && dual) begin
      assert (voted_reg == {f_other_heads, f_keep_heads});
      assert (anchor_reg == f_anchor && lo_reg == f_lo && hi_reg == f_hi);
    end
    if (f_past_valid) assert (vote_keep == f_vote_keep && vote_other == f_vote_other);
  end
  integer f_k;
  always @(*) begin
    if (f_past_valid) for (f_k = 0; f_k < DUAL_VOTES; f_k = f_k + 1) begin
      if (dual) assert (votes_keep_reg[f_k] == (f_keep_n > f_k));
      if (dual) assert (votes_other_reg[f_k] == (f_other_n > f_k));
    end
    if (f_past_valid) for (f_k = 1; f_k < DUAL_VOTES; f_k = f_k + 1) begin
      if (votes_keep_reg[f_k]) assert (votes_keep_reg[f_k - 1]);
      if (votes_other_reg[f_k]) assert (votes_other_reg[f_k - 1]);
    end
  end
  // Every mode and every documented transition is reachable.
  always @(posedge clk) begin
    if (f_past_valid && !rst && !f_rst_prev) begin
      cover (f_mode_prev == ACQUIRE && mode == NORMAL);
      cover (f_mode_prev == ACQUIRE && mode == REDUCED_1);
      cover (f_mode_prev == ACQUIRE && mode == REDUCED_2);
      cover (f_mode_prev == NORMAL && mode == REDUCED_1);          // track 2 lost support
      cover (f_mode_prev == REDUCED_1 && mode == NORMAL && !f_dual_prev);  // return to normal
      cover (f_mode_prev == REDUCED_2 && mode == NORMAL && !f_dual_prev);
      cover (f_valid_prev && mode == INCREMENTAL && !dual);        // the offset dropped
      cover (f_mode_prev == INCREMENTAL && !f_dual_prev && mode == NORMAL);  // a new lock
      cover (!f_dual_prev && dual);                                // a missed state
      cover (f_dual_prev && mode == NORMAL && offset == f_offset_prev);  // the count was right
      cover (f_dual_prev && mode == NORMAL && offset != f_offset_prev);  // one slot the other way
      cover (f_dual_prev && !dual && mode == INCREMENTAL);         // undecided: dropped
    end
  end
`endif

endmodule

`resetall
