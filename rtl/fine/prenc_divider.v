// SPDX-License-Identifier: Apache-2.0
// prenc_divider: floor(num / den), one quotient bit per clock (restoring division).
//
// A `start` in cycle k loads num and den; `done` is high for one cycle, cycle
// k + QUOTIENT_BITS + 2, with the quotient (held until the next start). A quotient
// that needs more than QUOTIENT_BITS bits, or den = 0, saturates to all ones.
// `cancel` drops a division under way (a `done` due in the same cycle still comes).
// Model: prenc.fine.velocity.Divider.
//
// The operands are registered first; the next cycle checks for saturation and starts
// the remainder as num's bits above the quotient's (below den, else the quotient
// saturates); then it takes one more bit of num a clock.
//
// Latency: QUOTIENT_BITS + 2 clocks from `start` to `done`.
//
// Parameters
//   NUM_BITS       numerator width, QUOTIENT_BITS + 1..128
//   DEN_BITS       denominator width, 1..64
//   QUOTIENT_BITS  quotient width, 1..63
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_divider #(
  parameter integer NUM_BITS      = 65,
  parameter integer DEN_BITS      = 27,
  parameter integer QUOTIENT_BITS = 49
) (
  input  wire                     clk,
  input  wire                     rst,
  input  wire                     start,
  input  wire                     cancel,
  input  wire [NUM_BITS-1:0]      num,
  input  wire [DEN_BITS-1:0]      den,
  output wire                     done,
  output wire [QUOTIENT_BITS-1:0] quotient
);

  generate
    if (QUOTIENT_BITS < 1 || QUOTIENT_BITS > 63) begin : g_bad_quotient_bits
      initial $display("ERROR: %m: parameter QUOTIENT_BITS = %0d is out of range 1..63",
                       QUOTIENT_BITS);
      prenc_divider_parameter_QUOTIENT_BITS_out_of_range_1_to_63 u_stop ();
    end
    if (NUM_BITS <= QUOTIENT_BITS || NUM_BITS > 128) begin : g_bad_num_bits
      initial $display("ERROR: %m: parameter NUM_BITS = %0d is out of range QUOTIENT_BITS + 1..128",
                       NUM_BITS);
      prenc_divider_parameter_NUM_BITS_out_of_range u_stop ();
    end
    if (DEN_BITS < 1 || DEN_BITS > 64) begin : g_bad_den_bits
      initial $display("ERROR: %m: parameter DEN_BITS = %0d is out of range 1..64", DEN_BITS);
      prenc_divider_parameter_DEN_BITS_out_of_range_1_to_64 u_stop ();
    end
  endgenerate

  localparam integer HIGH_BITS = NUM_BITS - QUOTIENT_BITS;  // num's bits above the quotient's
  localparam integer REM_BITS  = (HIGH_BITS > DEN_BITS) ? HIGH_BITS : DEN_BITS;
  localparam integer LEFT_BITS = $clog2(QUOTIENT_BITS + 1);

  reg [REM_BITS-1:0]      rem_reg;     // below den
  reg [QUOTIENT_BITS-1:0] bits_reg;    // num's low bits, shifted out; the quotient shifted in
  reg [DEN_BITS-1:0]      den_reg;
  reg [LEFT_BITS-1:0]     left_reg;
  reg                     saturated_reg;
  reg                     done_reg;
  reg [NUM_BITS-1:0]      num_reg;
  reg                     loaded_reg;  // operands in, the check and the first bit next

  wire [REM_BITS:0]   high     = {{(REM_BITS + 1 - HIGH_BITS){1'b0}},
                                  num_reg[NUM_BITS-1:QUOTIENT_BITS]};
  wire [REM_BITS:0]   den_held = {{(REM_BITS + 1 - DEN_BITS){1'b0}}, den_reg};
  wire [REM_BITS:0]   shifted  = {rem_reg, bits_reg[QUOTIENT_BITS-1]};
  wire                fits     = shifted >= den_held;
  wire [REM_BITS:0]   reduced  = fits ? shifted - den_held : shifted;   // below den again
  wire                unused_ok = &{1'b0, reduced[REM_BITS]};           // 0: below den

  always @(posedge clk) begin
    done_reg <= 1'b0;
    if (left_reg != {LEFT_BITS{1'b0}}) begin
      rem_reg  <= reduced[REM_BITS-1:0];
      bits_reg <= {bits_reg[QUOTIENT_BITS-2:0], fits};
      left_reg <= left_reg - 1'b1;
      if (left_reg == {{(LEFT_BITS - 1){1'b0}}, 1'b1}) begin
        done_reg <= 1'b1;
        if (saturated_reg) bits_reg <= {QUOTIENT_BITS{1'b1}};
      end
    end
    loaded_reg <= 1'b0;
    if (loaded_reg) begin
      rem_reg       <= high[REM_BITS-1:0];
      bits_reg      <= num_reg[QUOTIENT_BITS-1:0];
      left_reg      <= QUOTIENT_BITS[LEFT_BITS-1:0];
      saturated_reg <= (den_reg == {DEN_BITS{1'b0}}) || (high >= den_held);
    end
    if (start) begin
      num_reg    <= num;
      den_reg    <= den;
      loaded_reg <= 1'b1;
    end
    if (cancel) begin  // wins over a start in the same cycle
      left_reg   <= {LEFT_BITS{1'b0}};
      loaded_reg <= 1'b0;
    end
    if (rst) begin
      left_reg      <= {LEFT_BITS{1'b0}};
      done_reg      <= 1'b0;
      rem_reg       <= {REM_BITS{1'b0}};
      bits_reg      <= {QUOTIENT_BITS{1'b0}};
      den_reg       <= {DEN_BITS{1'b0}};
      saturated_reg <= 1'b0;
      num_reg       <= {NUM_BITS{1'b0}};
      loaded_reg    <= 1'b0;
    end
  end

  assign done     = done_reg;
  assign quotient = bits_reg;

endmodule

`resetall
