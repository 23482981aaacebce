// SPDX-License-Identifier: Apache-2.0
// prenc_sampler: mid-slot sampling strobes and the head readings taken there.
//
// The datasheet samples the code tracks at mid-slot: on A rising going CW (q 1 -> 2)
// and on A falling going CCW (q 2 -> 1). This module turns the quadrature decoder's
// steps into those strobes, each with its direction, and latches both heads as they
// were at the very input sample where A changed (with HEAD_DELAY = 1 the heads are
// delayed by the same pipeline as the decoder's registered step; with 0 the step comes
// on the same clock as the heads, from the decoder's *_next outputs), so a fast disc
// cannot move the heads on before they are read.
//
// Reversals: consecutive strobes in the same direction are one slot apart;
// consecutive strobes in opposite directions are the same mid-slot point crossed
// back (the disc turned round without reaching the next one, however much it
// dithered in between). strobe_moved tells the two apart, so the shift register
// moves the word only when the disc reached a new slot. The first strobe after
// reset or a break in continuity counts as moved.
//
// Landing readings (JUMP = 1, the core): an illegal transition (A and B changed
// together) lands the disc on a quarter boundary. When the quarter after it is 1 or 2,
// the landing point is at least a quarter slot from a slot boundary whichever way the
// disc moved (+2 quarters: p + 0.5 / p + 0.25; -2 quarters: p + 0.75 / p + 0.5), so the
// heads read whole slots there. The heads at that sample are strobed one clock later,
// unless a step or another illegal transition comes in between (one event per clock).
// They are evidence for the reader's two hypotheses, not a mid-slot sample.
//
// Latency: a strobe one clock after the decoder's step over a mid-slot edge (HEAD_DELAY
// = 1: after its registered step; 0: after its *_next step, a clock earlier).
//
// Parameters
//   JUMP         1: also strobe the landing reading after an illegal transition; 0:
//                mid-slot only
//   HEAD_DELAY   1: the step is the decoder's registered one, a clock after the heads'
//                sample; 0: the step is the decoder's *_next, with the heads' sample
//                (prenc_core: a clock less latency)
//
// Ports (outputs registered)
//   head1_in, head2_in   conditioned heads, same latency as the decoder's inputs
//   step, step_cw        from prenc_quadrature (HEAD_DELAY clocks after the input sample)
//   quarter              from prenc_quadrature: q after the step
//   break_in             continuity lost (an illegal transition): forget direction
//   strobe               a mid-slot sampling instant
//   strobe_cw            its direction: 1 CW (A rose), 0 CCW (A fell)
//   strobe_moved         the disc is in a new slot since the last strobe
//   strobe_head1/2       the heads at that instant

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_sampler #(
  parameter integer JUMP       = 0,
  parameter integer HEAD_DELAY = 1
) (
  input  wire       clk,
  input  wire       rst,
  input  wire       head1_in,
  input  wire       head2_in,
  input  wire       step,
  input  wire       step_cw,
  input  wire [1:0] quarter,
  input  wire       break_in,
  output wire       strobe,
  output wire       strobe_cw,
  output wire       strobe_moved,
  output wire       strobe_head1,
  output wire       strobe_head2
);

  generate
    if (JUMP != 0 && JUMP != 1) begin : g_bad_jump
      initial $display("ERROR: %m: parameter JUMP = %0d must be 0 or 1", JUMP);
      prenc_sampler_parameter_JUMP_must_be_0_or_1 u_stop ();
    end
    if (HEAD_DELAY != 0 && HEAD_DELAY != 1) begin : g_bad_head_delay
      initial $display("ERROR: %m: parameter HEAD_DELAY = %0d must be 0 or 1", HEAD_DELAY);
      prenc_sampler_parameter_HEAD_DELAY_must_be_0_or_1 u_stop ();
    end
  endgenerate

  // Heads delayed one clock, to line up with the decoder's step output.
  reg head1_d;
  reg head2_d;

  reg strobe_reg;
  reg strobe_cw_reg;
  reg strobe_moved_reg;
  reg strobe_head1_reg;
  reg strobe_head2_reg;
  reg have_last_reg;  // a strobe has been seen since reset or the last break
  reg last_cw_reg;    // direction of that strobe
  reg landing_reg;    // a landing reading waiting for a clock without an event
  reg landing_cw_reg;
  reg landing_head1_reg;
  reg landing_head2_reg;

  wire mid_slot = step & (step_cw ? (quarter == 2'd2) : (quarter == 2'd1));
  // The heads at the input sample of the step.
  wire head1 = (HEAD_DELAY == 1) ? head1_d : head1_in;
  wire head2 = (HEAD_DELAY == 1) ? head2_d : head2_in;

  always @(posedge clk) begin
    head1_d    <= head1_in;
    head2_d    <= head2_in;
    strobe_reg <= 1'b0;
    if (mid_slot) begin
      strobe_reg       <= 1'b1;
      strobe_cw_reg    <= step_cw;
      strobe_moved_reg <= ~have_last_reg | (step_cw == last_cw_reg);
      strobe_head1_reg <= head1;
      strobe_head2_reg <= head2;
      have_last_reg    <= 1'b1;
      last_cw_reg      <= step_cw;
    end else if (landing_reg && !step && !break_in) begin
      strobe_reg       <= 1'b1;
      strobe_cw_reg    <= landing_cw_reg;
      strobe_moved_reg <= 1'b1;
      strobe_head1_reg <= landing_head1_reg;
      strobe_head2_reg <= landing_head2_reg;
    end
    landing_reg       <= (JUMP == 1) & break_in & (quarter[1] ^ quarter[0]);
    landing_cw_reg    <= step_cw;
    landing_head1_reg <= head1;
    landing_head2_reg <= head2;
    if (break_in) begin
      have_last_reg <= 1'b0;
    end
    if (rst) begin
      strobe_reg    <= 1'b0;
      have_last_reg <= 1'b0;
      landing_reg   <= 1'b0;
    end
  end

  assign strobe       = strobe_reg;
  assign strobe_cw    = strobe_cw_reg;
  assign strobe_moved = strobe_moved_reg;
  assign strobe_head1 = strobe_head1_reg;
  assign strobe_head2 = strobe_head2_reg;

`ifdef FORMAL
  // Properties (formal/prenc_sampler.sby). The inputs obey the decoder's contract
  // (prenc_quadrature, proven in formal/prenc_quadrature.sby): the quarter moves by
  // one with a step (in step_cw's direction) and by two with a break, else it holds.
  reg       f_past_valid = 1'b0;
  reg [1:0] f_q_prev;
  reg       f_rst_prev;
  reg       f_mid_prev;       // last clock's input was a mid-slot step
  reg       f_cw_prev;
  reg       f_h1_prev;        // the heads at the input sample of last clock's step
  reg       f_h2_prev;
  reg       f_hin1;
  reg       f_hin2;
  reg       f_land_prev;      // the clock before last was a break into q = 1 or 2
  reg       f_event_prev;     // last clock had a step or a break
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_q_prev     <= quarter;
    f_rst_prev   <= rst;
    f_mid_prev   <= mid_slot;
    f_cw_prev    <= step_cw;
    f_hin1       <= head1_in;
    f_hin2       <= head2_in;
    // the heads at the step's sample: their input HEAD_DELAY clocks before the step
    f_h1_prev    <= (HEAD_DELAY == 1) ? f_hin1 : head1_in;
    f_h2_prev    <= (HEAD_DELAY == 1) ? f_hin2 : head2_in;
    f_land_prev  <= break_in & (quarter == 2'd1 || quarter == 2'd2);
    f_event_prev <= step | break_in;
  end
  // The landing reading's inputs (the clock before last) and the strobe history.
  reg f_land_prev2;
  reg f_land_h1;
  reg f_land_h2;
  reg f_land_cw;
  reg f_rst_prev2;
  reg f_have;        // a mid-slot strobe since reset or the last break
  reg f_last_cw;     // its direction
  reg f_have_prev;
  reg f_last_cw_prev;
  always @(posedge clk) begin
    f_land_prev2   <= f_land_prev;
    f_land_h1      <= f_h1_prev;
    f_land_h2      <= f_h2_prev;
    f_land_cw      <= f_cw_prev;
    f_rst_prev2    <= f_rst_prev;
    f_have_prev    <= f_have;
    f_last_cw_prev <= f_last_cw;
    if (mid_slot) begin
      f_have    <= 1'b1;
      f_last_cw <= step_cw;
    end
    if (break_in || rst) f_have <= 1'b0;
  end
  initial assume (rst);
  always @(*) begin
    if (f_past_valid) begin
      if (step) assume (quarter == f_q_prev + (step_cw ? 2'd1 : 2'd3) && !break_in);
      if (break_in) assume (quarter == f_q_prev + 2'd2);
      if (!step && !break_in) assume (quarter == f_q_prev);
    end
  end
  // Strobe history for "never two for one crossing".
  reg f_cw_since;   // since the last CW mid-slot strobe: passed q = 0, a CCW strobe or a break
  reg f_ccw_since;  // since the last CCW one: passed q = 3, a CW strobe or a break
  reg f_seen_cw;
  reg f_seen_ccw;
  always @(posedge clk) begin
    if (mid_slot && step_cw) begin
      f_cw_since <= 1'b0;
      f_seen_cw  <= 1'b1;
    end else if (quarter == 2'd0 || (mid_slot && !step_cw) || break_in) begin
      f_cw_since <= 1'b1;
    end
    if (mid_slot && !step_cw) begin
      f_ccw_since <= 1'b0;
      f_seen_ccw  <= 1'b1;
    end else if (quarter == 2'd3 || (mid_slot && step_cw) || break_in) begin
      f_ccw_since <= 1'b1;
    end
    if (rst) begin
      f_seen_cw  <= 1'b0;
      f_seen_ccw <= 1'b0;
    end
  end
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      // A strobe exactly one clock after each mid-slot step (A rising CW, A falling
      // CCW), with its direction and the heads of that input sample.
      if (f_mid_prev) begin
        assert (strobe && strobe_cw == f_cw_prev);
        assert (strobe_head1 == f_h1_prev && strobe_head2 == f_h2_prev);
      end
      // ... and no other strobe, but the landing reading (JUMP = 1): one clock after a
      // break into q = 1 or 2 when that clock has no event, with the heads of the
      // break's input sample and its direction, always a new slot.
      if (strobe && !f_mid_prev) begin
        assert (JUMP == 1 && f_land_prev2 && !f_event_prev);
        assert (strobe_head1 == f_land_h1 && strobe_head2 == f_land_h2);
        assert (strobe_cw == f_land_cw && strobe_moved);
      end
      if (f_land_prev2 && !f_event_prev && !f_mid_prev && !f_rst_prev2)
        assert (strobe == (JUMP == 1));
      if (!f_mid_prev && !(f_land_prev2 && !f_event_prev)) assert (!strobe);
      // A mid-slot strobe is in a new slot unless it crosses back the last strobe's
      // point (the other direction, no break since).
      if (f_mid_prev) assert (strobe_moved == (!f_have_prev || f_cw_prev == f_last_cw_prev));
      assert (have_last_reg == f_have && (!f_have || last_cw_reg == f_last_cw));
      // Never two strobes for one crossing (with its inductive invariant: after a CW
      // strobe the disc stays in q = 2, 3 until it passes q = 0 or strobes back).
      if (f_seen_cw && !f_cw_since) assert (f_q_prev == 2'd2 || f_q_prev == 2'd3);
      if (f_seen_ccw && !f_ccw_since) assert (f_q_prev == 2'd1 || f_q_prev == 2'd0);
      if (mid_slot && step_cw && f_seen_cw && !rst) assert (f_cw_since);
      if (mid_slot && !step_cw && f_seen_ccw && !rst) assert (f_ccw_since);
    end
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst) begin
      cover (strobe && strobe_cw);
      cover (strobe && !strobe_cw && !strobe_moved);  // a crossing back
      cover (strobe && !f_mid_prev);                  // a landing reading
    end
  end
`endif

endmodule

`resetall
