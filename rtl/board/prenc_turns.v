// SPDX-License-Identifier: Apache-2.0
// prenc_turns: a multi-turn position from the single-turn one and the incremental count.
//
// `full` = turns * 2^POS_BITS + position, counted from the first valid position after
// reset (turn 0). While `valid` it follows `position` across the zero crossing: each
// clock it moves by the shortest way to the new position (a valid position moves by
// at most a quarter slot per clock), so turns accumulate CW and count down CCW. While
// not valid it moves with the incremental count (quadrature steps), and when the
// position is valid again it takes the turn nearest to where the count brought it.
// So the turns survive a lost position as long as the disc moved less than half a
// turn more than the count saw (a missed quadrature state costs two quarters).
//
// Latency: one clock; turns and full are registered from the same clock's position,
// valid and count.
//
// Parameters
//   POS_BITS    single-turn bits (pos_hyb: N + 2), 2..30
//   TURN_BITS   multi-turn bits, 1..32 (the turn count wraps modulo 2^TURN_BITS)
//
// Ports
//   position, valid   the core's pos_hyb and pos_valid (same clock)
//   count             the low POS_BITS of the core's incremental count (quadrature
//                     steps; the count moves at most one step per clock)
//   turns, full       turns since the first valid position; {turns, position}
//   placed            a valid position was seen since reset (turns mean something)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_turns #(
  parameter integer POS_BITS   = 12,
  parameter integer TURN_BITS  = 12
) (
  input  wire                          clk,
  input  wire                          rst,
  input  wire [POS_BITS-1:0]           position,
  input  wire                          valid,
  input  wire [POS_BITS-1:0]           count,
  output wire [TURN_BITS-1:0]          turns,
  output wire [TURN_BITS+POS_BITS-1:0] full,
  output wire                          placed
);

  generate
    if (POS_BITS < 2 || POS_BITS > 30) begin : g_bad_pos_bits
      initial $display("ERROR: %m: parameter POS_BITS = %0d is out of range 2..30", POS_BITS);
      prenc_turns_parameter_POS_BITS_out_of_range_2_to_30 u_stop ();
    end
    if (TURN_BITS < 1 || TURN_BITS > 32) begin : g_bad_turn_bits
      initial $display("ERROR: %m: parameter TURN_BITS = %0d is out of range 1..32", TURN_BITS);
      prenc_turns_parameter_TURN_BITS_out_of_range_1_to_32 u_stop ();
    end
  endgenerate

  localparam integer W = TURN_BITS + POS_BITS;

  reg [W-1:0]          full_reg;
  reg                  placed_reg;
  reg [POS_BITS-1:0]   count_prev;

  // The shortest way from the last position to this one, as a signed step.
  wire [POS_BITS-1:0] way      = position - full_reg[POS_BITS-1:0];
  wire [W-1:0]        way_ext  = {{TURN_BITS{way[POS_BITS-1]}}, way};
  // The count's move since the last clock.
  wire [POS_BITS-1:0] moved     = count - count_prev;
  wire [W-1:0]        moved_ext = {{TURN_BITS{moved[POS_BITS-1]}}, moved};

  always @(posedge clk) begin
    count_prev <= count;
    if (valid && !placed_reg) begin
      full_reg   <= {{TURN_BITS{1'b0}}, position};
      placed_reg <= 1'b1;
    end else if (valid) begin
      full_reg <= full_reg + way_ext;
    end else begin
      full_reg <= full_reg + moved_ext;
    end
    if (rst) begin
      full_reg   <= {W{1'b0}};
      placed_reg <= 1'b0;
      count_prev <= count;
    end
  end

  assign turns  = full_reg[W-1:POS_BITS];
  assign full   = full_reg;
  assign placed = placed_reg;

`ifdef FORMAL
  // Properties (formal/prenc_turns.sby): against a disc that turns by at most one
  // position step a clock (its multi-turn place f_true, chosen by the solver), read
  // as `position` whenever valid (any pattern of valid), with a count that moves
  // with it while the position is not valid (while valid it may jump anywhere: missed
  // states are forgiven then): from the first valid position on, `full` is the disc's
  // multi-turn place (one clock later) less its place at that first position, plus
  // that position: the turns accumulate both ways and survive every loss of valid.
  // `placed` tells whether a valid position was seen since reset.
  reg f_past_valid = 1'b0;
  reg f_rst_prev;
  (* anyseq *)   reg [1:0]          f_move;  // 0 hold, 1 CW, 3 CCW (2: hold)
  (* anyseq *)   reg [POS_BITS-1:0] f_new_offset;  // the count's slip, while valid
  reg [POS_BITS-1:0] f_offset_prev;
  wire [POS_BITS-1:0] f_count_offset = valid ? f_new_offset : f_offset_prev;
  reg f_seen;  // a valid position since reset
  reg [W-1:0] f_true;
  reg [W-1:0] f_true_prev;
  reg [W-1:0] f_k;  // full - f_true from the first valid position on
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_rst_prev   <= rst;
    f_true       <= f_true + ((f_move == 2'd1) ? {{(W - 1){1'b0}}, 1'b1} :
                              (f_move == 2'd3) ? {W{1'b1}} : {W{1'b0}});
    f_true_prev  <= f_true;
    if (valid && !placed_reg) f_k <= {{TURN_BITS{1'b0}}, position} - f_true;
    f_offset_prev <= f_count_offset;
    f_seen        <= !rst && (f_seen || valid);
  end
  initial assume (rst);
  always @(*) begin
    if (valid) assume (position == f_true[POS_BITS-1:0]);
    assume (count == f_true[POS_BITS-1:0] + f_count_offset);
  end
  always @(*) begin
    if (f_past_valid && !f_rst_prev) begin
      assert (f_true == f_true_prev || f_true == f_true_prev + 1'b1 ||
              f_true == f_true_prev - 1'b1);
      if (placed_reg) assert (full_reg == f_true_prev + f_k);
      if (placed_reg) assert (f_k[POS_BITS-1:0] == {POS_BITS{1'b0}});  // whole turns
      assert (count_prev == f_true_prev[POS_BITS-1:0] + f_offset_prev);
    end
    if (f_past_valid && f_rst_prev) assert (!placed_reg && full_reg == {W{1'b0}});
    if (f_past_valid) assert (placed_reg == f_seen);
  end
  always @(posedge clk) begin
    if (f_past_valid && !rst && placed_reg) begin
      cover (turns == 2);
      cover (turns == {TURN_BITS{1'b1}});  // -1: counted down past the first turn
    end
  end
`endif

endmodule

`resetall
