// SPDX-License-Identifier: Apache-2.0
// prenc_decoder_quarter: the quarter the quadrature decoder is in, in the core's
// position count.
//
// The core's pos_hyb follows the decoder's step by 4 clocks (prenc_position). So the
// quarter the decoder entered with this cycle's step is pos_hyb plus the steps that
// pos_hyb does not show yet: this cycle's and the three before (+1 clockwise, -1
// counter-clockwise). It is what prenc_cal_lookup is asked for, and where
// prenc_edge_capture's edges are.
// Model: prenc.cal.decoder_quarter.DecoderQuarter.
//
// Latency: none, combinational: the quarter the decoder's registered step entered, on
// the step's own clock.
//
// Parameters
//   N   code word length, 2..24 (pos_hyb and quarter are N + 2 bits)
//
// Ports
//   pos_hyb            prenc_core's
//   step, step_cw      the decoder's registered step and its direction
//   quarter            pos_hyb + the steps of this cycle and the 3 before
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_decoder_quarter #(
  parameter integer N = 10
) (
  input  wire         clk,
  input  wire         rst,
  input  wire [N+1:0] pos_hyb,
  input  wire         step,
  input  wire         step_cw,
  output wire [N+1:0] quarter
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_decoder_quarter_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  localparam [N+1:0] UP   = {{(N + 1){1'b0}}, 1'b1};
  localparam [N+1:0] DOWN = {(N + 2){1'b1}};
  localparam [N+1:0] STAY = {(N + 2){1'b0}};

  reg [2:0] step_reg;   // a step, in each of the 3 cycles before
  reg [2:0] cw_reg;

  wire [N+1:0] moved_0 = step ? (step_cw ? UP : DOWN) : STAY;
  wire [N+1:0] moved_1 = step_reg[0] ? (cw_reg[0] ? UP : DOWN) : STAY;
  wire [N+1:0] moved_2 = step_reg[1] ? (cw_reg[1] ? UP : DOWN) : STAY;
  wire [N+1:0] moved_3 = step_reg[2] ? (cw_reg[2] ? UP : DOWN) : STAY;

  always @(posedge clk) begin
    step_reg <= {step_reg[1:0], step};
    cw_reg   <= {cw_reg[1:0], step_cw};
    if (rst) begin
      step_reg <= 3'b000;
      cw_reg   <= 3'b000;
    end
  end

  assign quarter = pos_hyb + moved_0 + moved_1 + moved_2 + moved_3;

endmodule

`resetall
