// SPDX-License-Identifier: Apache-2.0
// prenc_cal_lookup: the calibration table in block RAM, and the corrections of a
// quarter's two edges, one clock after the quarter is asked for (docs/calibration.md).
//
// The table (4 x 2^N words: c[x], the true place of edge x is x + c[x] / 2^12
// quarters) sits in one memory with one read port and one write port, so that every
// device holds it in plain block RAM. A quarter q needs c[q] and c[q + 1]; two slots
// hold the last two words read, each with the address it holds (its tag):
// - each cycle, for the quarter asked, a slot keeps its word, takes the other slot's
//   (the disc moved one quarter: the shared edge), or is filled by the read; the
//   memory reads c[q] if the lower slot needs it, else c[q + 1];
// - so a move of one quarter per clock, either way, keeps both slots full; a jump (the
//   core's position set anew) takes two clocks; `ok` says both hold q's words;
// - a write changes a word from the next clock on; a slot that holds its address, or
//   reads it in the same cycle (the read returns the old word), is emptied.
// Model: prenc.cal.lookup.CalLookup.
//
// Latency: c_lo and c_hi hold the words of the quarter asked in the cycle before (one
// clock); a jump to another quarter takes two clocks, and `ok` says when both words are
// there.
//
// Parameters
//   N          code word length, 2..16 (the table is 2^(N+2) words of 16 bits)
//   CAL_FILE   the table ($readmemh, prenc.cal.table's format; checked in simulation);
//              "" : all zero, for a table written at run time
//
// Ports
//   quarter        the quarter asked for, N + 2 bits
//   write, address, data   a word of the table written (two's complement, 2^-12 quarter)
//   c_lo, c_hi     c[q], c[q + 1] of the quarter asked in the cycle before
//   ok             both are q's
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_cal_lookup #(
  parameter integer N        = 10,
  parameter         CAL_FILE = ""
) (
  input  wire         clk,
  input  wire         rst,
  input  wire [N+1:0] quarter,
  input  wire         write,
  input  wire [N+1:0] address,
  input  wire [15:0]  data,
  output wire [15:0]  c_lo,
  output wire [15:0]  c_hi,
  output wire         ok
);

  generate
    if (N < 2 || N > 16) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..16", N);
      prenc_cal_lookup_parameter_N_out_of_range_2_to_16 u_stop ();
    end
  endgenerate

  localparam integer QB    = N + 2;
  localparam integer DEPTH = 1 << QB;

  reg [15:0] table_mem [0:DEPTH-1];

  generate
    if (CAL_FILE == "") begin : g_zero
      integer i;
      initial begin
        for (i = 0; i < DEPTH; i = i + 1) begin
          table_mem[i] = 16'd0;
        end
      end
    end else begin : g_file
      initial $readmemh(CAL_FILE, table_mem);
`ifndef SYNTHESIS
      // A missing or short table must not become an all-X or all-zero one.
      prenc_rom_check #(
        .NAME  ("CAL_FILE"),
        .FILE  (CAL_FILE),
        .DEPTH (DEPTH),
        .WIDTH (16)
      ) u_cal_check ();
`endif
    end
  endgenerate

  reg [15:0]   word_reg;      // the memory's read register
  reg [15:0]   lo_hold_reg;
  reg [15:0]   hi_hold_reg;
  reg          lo_word_reg;   // the slot's word is the read's
  reg          hi_word_reg;
  reg [QB-1:0] lo_tag_reg;
  reg [QB-1:0] hi_tag_reg;
  reg          lo_ok_reg;
  reg          hi_ok_reg;

  wire [15:0]   lo_val    = lo_word_reg ? word_reg : lo_hold_reg;
  wire [15:0]   hi_val    = hi_word_reg ? word_reg : hi_hold_reg;
  wire [QB-1:0] next      = quarter + 1'b1;
  wire          lo_keep   = lo_ok_reg && (lo_tag_reg == quarter);
  wire          lo_swap   = !lo_keep && hi_ok_reg && (hi_tag_reg == quarter);
  wire          hi_keep   = hi_ok_reg && (hi_tag_reg == next);
  wire          hi_swap   = !hi_keep && lo_ok_reg && (lo_tag_reg == next);
  wire          read_lo   = !(lo_keep || lo_swap);
  wire          read_hi   = !(hi_keep || hi_swap) && !read_lo;
  wire [QB-1:0] read_addr = read_lo ? quarter : next;

  always @(posedge clk) begin
    if (write) begin
      table_mem[address] <= data;
    end
    word_reg <= table_mem[read_addr];
  end

  always @(posedge clk) begin
    lo_hold_reg <= lo_swap ? hi_val : lo_val;
    hi_hold_reg <= hi_swap ? lo_val : hi_val;
    lo_word_reg <= read_lo;
    hi_word_reg <= read_hi;
    lo_tag_reg  <= quarter;
    hi_tag_reg  <= next;
    lo_ok_reg   <= !(write && address == quarter);
    hi_ok_reg   <= (hi_keep || hi_swap || read_hi) && !(write && address == next);
    if (rst) begin
      lo_word_reg <= 1'b0;
      hi_word_reg <= 1'b0;
      lo_tag_reg  <= {QB{1'b0}};
      hi_tag_reg  <= {QB{1'b0}};
      lo_ok_reg   <= 1'b0;
      hi_ok_reg   <= 1'b0;
    end
  end

  assign c_lo = lo_val;
  assign c_hi = hi_val;
  assign ok   = lo_ok_reg & hi_ok_reg;

endmodule

`resetall
