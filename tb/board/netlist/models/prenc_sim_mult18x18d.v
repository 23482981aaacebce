// SPDX-License-Identifier: Apache-2.0
// MULT18X18D, the ECP5's 18 x 18 multiplier, for simulating Yosys's ECP5 netlists
// (tb/board/netlist). Yosys ships this cell only as a black box; this model follows
// Lattice's ECP5 sysDSP usage guide (FPGA-TN-02205) for the one mode Yosys's
// multiplier mapping makes: no register (REG_INPUTA/B/C_CLK, REG_PIPELINE_CLK,
// REG_OUTPUT_CLK all "NONE"), operands from the A and B pins (SOURCEA/B 0), each
// signed or unsigned by SIGNEDA/SIGNEDB. Any other mode stops the simulation.
//
// P = A x B (36 bits), combinational.

`resetall
`timescale 1ns / 1ps
`default_nettype none

module MULT18X18D #(
  parameter REG_INPUTA_CLK    = "NONE",
  parameter REG_INPUTB_CLK    = "NONE",
  parameter REG_INPUTC_CLK    = "NONE",
  parameter REG_PIPELINE_CLK  = "NONE",
  parameter REG_OUTPUT_CLK    = "NONE",
  parameter CLK0_DIV          = "ENABLED",
  parameter CLK1_DIV          = "ENABLED",
  parameter CLK2_DIV          = "ENABLED",
  parameter CLK3_DIV          = "ENABLED",
  parameter GSR               = "ENABLED",
  parameter SOURCEB_MODE      = "B_SHIFT",
  parameter MULT_BYPASS       = "DISABLED",
  parameter RESETMODE         = "SYNC"
) (
  input  wire A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0,
  input  wire B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0,
  input  wire C17, C16, C15, C14, C13, C12, C11, C10, C9, C8, C7, C6, C5, C4, C3, C2, C1, C0,
  input  wire SIGNEDA, SIGNEDB, SOURCEA, SOURCEB,
  input  wire CE0, CE1, CE2, CE3, CLK0, CLK1, CLK2, CLK3, RST0, RST1, RST2, RST3,
  output wire P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24,
  output wire P23, P22, P21, P20, P19, P18, P17, P16, P15, P14, P13, P12,
  output wire P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0
);

  initial begin
    if (REG_INPUTA_CLK != "NONE" || REG_INPUTB_CLK != "NONE" || REG_INPUTC_CLK != "NONE" ||
        REG_PIPELINE_CLK != "NONE" || REG_OUTPUT_CLK != "NONE" || MULT_BYPASS != "DISABLED") begin
      $display("ERROR: %m: MULT18X18D with a register or a bypass is not modelled");
      $finish;
    end
  end

  wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
  wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};
  wire signed [18:0] a_ext = {SIGNEDA & a[17], a};
  wire signed [18:0] b_ext = {SIGNEDB & b[17], b};
  wire signed [37:0] p = a_ext * b_ext;

  always @(*) begin
    if (SOURCEA !== 1'b0 || SOURCEB !== 1'b0) begin
      $display("ERROR: %m: MULT18X18D's shift inputs (SOURCEA/B = 1) are not modelled");
      $finish;
    end
  end

  assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24,
          P23, P22, P21, P20, P19, P18, P17, P16, P15, P14, P13, P12,
          P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p[35:0];

endmodule

`resetall
