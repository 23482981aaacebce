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

endmodule

`resetall
