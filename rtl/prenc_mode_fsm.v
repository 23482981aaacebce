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
// The arithmetic behind LOCK_BOTH / LOCK_ONE: docs/architecture.md.
// Model: prenc.mode_fsm.ModeFsm (decisions registered; flush, law_on and realign are
// one-clock pulses to the track words).
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
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_mode_fsm #(
  parameter integer N          = 10,
  parameter integer LOCK_BOTH  = (N < 8) ? 3 : 2,
  parameter integer LOCK_ONE   = (N < 8) ? N + 5 : N + 2,
  parameter integer LOCK_EXTRA = 3,
  parameter integer DUAL_VOTES = 3,
  parameter integer DUAL_SPAN  = 12
) (
  input  wire         clk,
  input  wire         rst,
  // J1: one strobe or illegal transition, both tracks
  input  wire         strobe,
  input  wire         illegal,
  input  wire         illegal_cw,
  input  wire [N-1:0] slot,
  input  wire [1:0]   full,
  input  wire [N-1:0] off1,
  input  wire [N-1:0] off2,
  input  wire [5:0]   span1,
  input  wire [5:0]   span2,
  input  wire [1:0]   settled,
  input  wire [1:0]   quiet,
  input  wire [1:0]   checked,
  input  wire [1:0]   mismatch,
  input  wire [1:0]   mismatch_lo,
  input  wire [1:0]   mismatch_hi,
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
  endgenerate

  localparam [2:0] ACQUIRE     = 3'd0;
  localparam [2:0] NORMAL      = 3'd1;
  localparam [2:0] REDUCED_1   = 3'd2;
  localparam [2:0] REDUCED_2   = 3'd3;
  localparam [2:0] INCREMENTAL = 3'd4;
  localparam [31:0] NEED_BOTH32 = LOCK_BOTH - 1;
  localparam [31:0] NEED_ONE32  = LOCK_ONE - 1;
  localparam [31:0] VOTES32     = DUAL_VOTES;
  localparam [31:0] SPAN32      = DUAL_SPAN;
  localparam [31:0] DEEP_BOTH32 = LOCK_BOTH - 1 + LOCK_EXTRA;
  localparam [31:0] DEEP_ONE32  = LOCK_ONE - 1 + LOCK_EXTRA;
  localparam [5:0]  NEED_BOTH   = NEED_BOTH32[5:0];
  localparam [5:0]  NEED_ONE    = NEED_ONE32[5:0];
  localparam [5:0]  DEEP_BOTH   = DEEP_BOTH32[5:0];
  localparam [5:0]  DEEP_ONE    = DEEP_ONE32[5:0];
  localparam [2:0]  VOTES       = VOTES32[2:0];
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
  reg [2:0]          votes_keep_reg;
  reg [2:0]          votes_other_reg;
  reg [3:0]          voted_reg;     // {other by 2, other by 1, keep by 2, keep by 1}
  reg [1:0]          flush_reg;
  reg [1:0]          law_on_reg;
  reg [1:0]          realign_reg;  // {up, down}

  wire valid_now = (mode_reg == NORMAL) | (mode_reg == REDUCED_1) | (mode_reg == REDUCED_2);
  wire locked    = valid_now | dual_reg;
  // What the tracks will be once last clock's pulses land.
  wire [1:0] sup    = (supported & ~flush_reg) | law_on_reg;
  wire [1:0] lawish = (law & ~flush_reg) | law_on_reg;
  // Lock evidence, in parallel with the state logic.
  wire [1:0] ready   = full & settled;
  wire       agree12 = (off1 == off2);
  wire [5:0] need_both = (&quiet) ? NEED_BOTH : DEEP_BOTH;
  wire [5:0] need_one1 = quiet[0] ? NEED_ONE : DEEP_ONE;
  wire [5:0] need_one2 = quiet[1] ? NEED_ONE : DEEP_ONE;
  wire       both_ok = ready[0] & ready[1] & agree12 & (span1 >= need_both) & (span2 >= need_both);
  // One head alone, unless the other is settled on another offset.
  wire       one1_ok = ready[0] & (span1 >= need_one1) & ~(ready[1] & ~agree12);
  wire       one2_ok = ready[1] & (span2 >= need_one2) & ~(ready[0] & ~agree12);
  wire       on1     = (off1 == offset_reg);
  wire       on2     = (off2 == offset_reg);
  // Dual: where this strobe is, relative to the transition.
  wire [N-1:0] rel_n = slot - anchor_reg;
  wire signed [RW-1:0] rel;
  wire         far;
  generate
    if (N > RW) begin : g_rel_wide
      wire [N-RW:0] top = rel_n[N-1:RW-1];
      wire signed [RW-1:0] rel_w = rel_n[RW-1:0];
      assign far = ~((&top) | ~(|top)) | (rel_w > SPAN_P) | (rel_w < SPAN_M);
      assign rel = rel_n[RW-1:0];
    end else begin : g_rel_narrow
      wire signed [RW-1:0] rel_x = {{(RW - N){rel_n[N-1]}}, rel_n};
      assign far = (rel_x > SPAN_P) | (rel_x < SPAN_M);
      assign rel = rel_x;
    end
  endgenerate
  wire       fresh = (rel < lo_reg) | (rel > hi_reg);
  wire [1:0] alt   = dual_cw_reg ? mismatch_lo : mismatch_hi;
  wire [1:0] vote  = checked & (mismatch ^ alt);
  wire [1:0] vote_keep  = vote & ~mismatch;
  wire [1:0] vote_other = vote & mismatch;
  wire [3:0] keep_sum   = {1'b0, votes_keep_reg} + {3'd0, vote_keep[0]} + {3'd0, vote_keep[1]};
  wire [3:0] other_sum  = {1'b0, votes_other_reg} + {3'd0, vote_other[0]} + {3'd0, vote_other[1]};
  wire [2:0] keep_new   = (keep_sum > {1'b0, VOTES}) ? VOTES : keep_sum[2:0];
  wire [2:0] other_new  = (other_sum > {1'b0, VOTES}) ? VOTES : other_sum[2:0];
  wire [3:0] voted_new  = voted_reg | {vote_other, vote_keep};

  reg [2:0]           mode_next;
  reg [N-1:0]         offset_next;
  reg                 dual_next;
  reg                 dual_cw_next;
  reg [N-1:0]         anchor_next;
  reg signed [RW-1:0] lo_next;
  reg signed [RW-1:0] hi_next;
  reg [2:0]           votes_keep_next;
  reg [2:0]           votes_other_next;
  reg [3:0]           voted_next;
  reg [1:0]           flush_next;
  reg [1:0]           law_on_next;
  reg [1:0]           realign_next;
  reg                 locked_now;
  reg                 drop;
  reg [1:0]           s;

  always @* begin
    mode_next        = mode_reg;
    offset_next      = offset_reg;
    dual_next        = dual_reg;
    dual_cw_next     = dual_cw_reg;
    anchor_next      = anchor_reg;
    lo_next          = lo_reg;
    hi_next          = hi_reg;
    votes_keep_next  = votes_keep_reg;
    votes_other_next = votes_other_reg;
    voted_next       = voted_reg;
    flush_next       = 2'b00;
    law_on_next      = 2'b00;
    realign_next     = 2'b00;
    locked_now       = 1'b0;
    drop             = 1'b0;
    if (illegal) begin
      if (valid_now && !dual_reg && sup == 2'b11) begin
        dual_next        = 1'b1;
        dual_cw_next     = illegal_cw;
        mode_next        = INCREMENTAL;
        anchor_next      = slot;
        lo_next          = 1;
        hi_next          = 0;
        votes_keep_next  = 3'd0;
        votes_other_next = 3'd0;
        voted_next       = 4'd0;
      end else if (locked) begin
        drop = 1'b1;
      end
    end else if (strobe && !locked) begin
      if (both_ok) begin
        offset_next = off1;
        law_on_next = 2'b11;
        mode_next   = NORMAL;
        locked_now  = 1'b1;
      end else if (one1_ok) begin
        offset_next = off1;
        law_on_next = 2'b01;
        mode_next   = REDUCED_1;
        locked_now  = 1'b1;
      end else if (one2_ok) begin
        offset_next = off2;
        law_on_next = 2'b10;
        mode_next   = REDUCED_2;
        locked_now  = 1'b1;
      end
    end else if (strobe && !dual_reg) begin
      law_on_next = {full[1] & ~lawish[1] & on2, full[0] & ~lawish[0] & on1};
    end else if (strobe) begin
      if (far) begin
        drop = 1'b1;
      end else if (fresh) begin
        lo_next          = (rel < lo_reg) ? rel : lo_reg;
        hi_next          = (rel > hi_reg) ? rel : hi_reg;
        votes_keep_next  = keep_new;
        votes_other_next = other_new;
        voted_next       = voted_new;
        if (keep_new != 3'd0 && other_new != 3'd0) begin
          drop = 1'b1;
        end else if (keep_new >= VOTES && voted_new[0] && voted_new[1]) begin
          dual_next = 1'b0;
          mode_next = NORMAL;
        end else if (other_new >= VOTES && voted_new[2] && voted_new[3]) begin
          // The other way: the count is one slot off; the offset takes it.
          dual_next    = 1'b0;
          mode_next    = NORMAL;
          offset_next  = dual_cw_reg ? offset_reg - 1'b1 : offset_reg + 1'b1;
          realign_next = dual_cw_reg ? 2'b01 : 2'b10;
        end
      end
    end
    // Modes from support, every clock, while the offset stands.
    s = sup | law_on_next;
    if (drop) begin
      flush_next = 2'b11;
      dual_next  = 1'b0;
      mode_next  = INCREMENTAL;
    end else if (dual_next) begin
      if (sup != 2'b11) begin
        flush_next = 2'b11;
        dual_next  = 1'b0;
        mode_next  = INCREMENTAL;
      end
    end else if ((mode_next == NORMAL || mode_next == REDUCED_1 || mode_next == REDUCED_2) &&
                 !locked_now) begin
      case (s)
        2'b11:   mode_next = NORMAL;
        2'b01:   mode_next = REDUCED_1;
        2'b10:   mode_next = REDUCED_2;
        default: begin
          flush_next = 2'b11;
          mode_next  = INCREMENTAL;
        end
      endcase
    end
  end

  always @(posedge clk) begin
    mode_reg        <= mode_next;
    offset_reg      <= offset_next;
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
      votes_keep_reg  <= 3'd0;
      votes_other_reg <= 3'd0;
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

endmodule

`resetall
