// SPDX-License-Identifier: Apache-2.0
// prenc_converter: parallel lookup converter, code word -> absolute slot.
//
// A registered ROM read: the N-bit code word w(p) presented with word_valid on
// one clock gives its slot p on pos with pos_valid on the next (latency 1 clock,
// whatever N), where a serial converter steps the LFSR law up to 2^N - 1 times.
// The table (address w(p), data p) comes from `prenc rom --format hex`; it maps to
// block RAM in synthesis (registered read, no reset on the data register).
//
// Latency: one clock, from word_valid and word to pos_valid and pos.
//
// Parameters
//   N         code word length, 2..24 (2^N words of N bits)
//   ROM_FILE  $readmemh file with exactly 2^N words; a missing or short file stops
//             simulation at time 0 with a message, and stops Yosys too.
//
// Ports
//   clk, rst     one clock; synchronous active-high reset (clears pos_valid only)
//   word_valid   word holds a code word to convert
//   word         code word w(p), s(p) in the MSB
//   pos_valid    pos holds the slot of the word presented one clock earlier
//   pos          slot p; holds its value while pos_valid is low

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_converter #(
  parameter integer N        = 10,
  parameter         ROM_FILE = "prenc_rom_n10.hex"
`ifdef FORMAL
  ,
  parameter [31:0]  F_TAPS   = 32'h0000_0204  // the disc's taps, for the properties only
`endif
) (
  input  wire         clk,
  input  wire         rst,
  input  wire         word_valid,
  input  wire [N-1:0] word,
  output wire         pos_valid,
  output wire [N-1:0] pos
);

  localparam integer DEPTH = 1 << N;

  // Illegal parameters stop elaboration in Verilator, Icarus and Yosys alike: the
  // missing module below names the problem; Yosys also prints the $display.
  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_converter_parameter_N_out_of_range_2_to_24 u_stop ();
    end
  endgenerate

  reg [N-1:0] rom [0:DEPTH-1];
  initial $readmemh(ROM_FILE, rom);

  reg [N-1:0] pos_reg;
  reg         pos_valid_reg;

  always @(posedge clk) begin
    if (word_valid) begin
      pos_reg <= rom[word];
    end
  end

  always @(posedge clk) begin
    pos_valid_reg <= word_valid;
    if (rst) begin
      pos_valid_reg <= 1'b0;
    end
  end

  assign pos       = pos_reg;
  assign pos_valid = pos_valid_reg;

`ifndef SYNTHESIS
  // A missing or short ROM file must not become an all-X or all-zero ROM.
  prenc_rom_check #(
    .NAME  ("ROM_FILE"),
    .FILE  (ROM_FILE),
    .DEPTH (DEPTH),
    .WIDTH (N)
  ) u_rom_check ();
`endif

`ifdef FORMAL
  // Properties (formal/prenc_converter.sby): one clock after a valid word, the output
  // is the slot p whose window W(p) is that word, on the disc as the datasheet builds
  // it (formal/prenc_disc_reference.vh): the ROM file is checked, not trusted.
  localparam [31:0] TAPS = F_TAPS;
  `include "prenc_disc_reference.vh"
  reg         f_past_valid = 1'b0;
  reg         f_rst_prev;
  reg         f_valid_prev;
  reg [N-1:0] f_word_prev;
  reg [N-1:0] f_slot;
  integer     f_p;
  always @(*) begin
    f_slot = {N{1'b0}};
    for (f_p = 0; f_p < F_L; f_p = f_p + 1) begin
      if (f_window(f_p) == f_word_prev) f_slot = f_p[N-1:0];
    end
  end
  always @(posedge clk) begin
    f_past_valid <= 1'b1;
    f_rst_prev   <= rst;
    f_valid_prev <= word_valid;
    f_word_prev  <= word;
  end
  initial assume (rst);
  always @(*) begin
    if (f_past_valid && f_rst_prev) assert (!pos_valid);
    if (f_past_valid && !f_rst_prev) begin
      assert (pos_valid == f_valid_prev);
      if (f_valid_prev) assert (pos == f_slot);
    end
  end
`endif

endmodule

`resetall
