// SPDX-License-Identifier: Apache-2.0
// prenc_cal_lookup: the calibration table in block RAM, and the corrections of a
// quarter's two edges (docs/calibration.md).
//
// The table (4 x 2^N words: c[x], the true place of edge x is x + c[x] / 2^12
// quarters) sits in one memory with one read port and one write port, so that every
// device holds it in plain block RAM. A quarter q needs c[q] and c[q + 1]: when the
// pair on the outputs (c_lo, c_hi) is not the quarter asked's, the memory reads c[q],
// then c[q + 1], and the pair and its quarter (pair_quarter) change together on the
// clock after the second read. Until then they hold the last pair: a consumer uses
// them when pair_quarter is its quarter. A quarter that changes during a read is read
// after it. A write to the table empties the pair (`ok` 0) and spoils a read under
// way, so that a pair never holds a word older than the last write.
// Model: prenc.cal.lookup.CalLookup.
//
// Latency: the pair of a quarter asked from clock t on (no read under way) is on the
// outputs from clock t + 3, and from t + 5 at most if a read was under way.
//
// Parameters
//   N          code word length, 2..16 (the table is 2^(N+2) words of 16 bits)
//   CAL_FILE   the table ($readmemh, prenc.cal.table's format; checked in simulation);
//              "" : all zero, for a table written at run time
//
// Ports
//   quarter        the quarter asked for, N + 2 bits
//   write, address, data   a word of the table written (two's complement, 2^-12 quarter)
//   c_lo, c_hi     c[q], c[q + 1] of q = pair_quarter
//   pair_quarter   the quarter whose pair c_lo, c_hi are
//   ok             the pair has been read since reset and the last write
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
  output wire [N+1:0] pair_quarter,
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

  // A read of the word being written is never used (the write spoils the read), so the
  // block RAM needs no bypass for it (no_rw_check).
  (* no_rw_check *)
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
      prenc_rom_check #(
        .NAME  ("CAL_FILE"),
        .FILE  (CAL_FILE),
        .DEPTH (DEPTH),
        .WIDTH (16)
      ) u_cal_check ();
`endif
    end
  endgenerate

  // The reads. In IDLE the memory reads the quarter asked every clock, and the quarter
  // is registered (asked_reg); the clock after, if the pair is not that quarter's (the
  // comparison between registers, so that the quarter's own path from the core ends at
  // a register and the memory's address), c[q] is there: it is kept, c[q + 1] is asked
  // (GO), and in READ_HI it comes and the pair is loaded, unless the table was written
  // since the quarter was asked. A read starts the clock after its quarter was asked,
  // the pair is loaded two clocks after that: as the model's IDLE, READ_LO, READ_HI.
  localparam [0:0] IDLE = 1'b0, READ_HI = 1'b1;

  reg          state_reg;
  reg          asked_now_reg; // asked_reg was registered by the clock before (an IDLE
                              // clock that did not go)
  reg [QB-1:0] asked_reg;     // the quarter asked, then being read
  reg [15:0]   word_reg;      // the memory's read register
  reg [15:0]   lo_reg;        // c[q], until its pair is loaded
  reg          dirty_reg;     // the table was written since the quarter was asked
  reg          ok_d_reg;      // ok_reg of the clock before
  reg [15:0]   c_lo_reg;      // the pair
  reg [15:0]   c_hi_reg;
  reg [QB-1:0] pair_reg;
  reg          ok_reg;

  wire          go        = (state_reg == IDLE) && asked_now_reg &&
                            (!ok_d_reg || asked_reg != pair_reg);
  wire [QB-1:0] read_addr = go ? asked_reg + 1'b1 : quarter;

  always @(posedge clk) begin
    if (write) begin
      table_mem[address] <= data;
    end
    word_reg <= table_mem[read_addr];   // (as the same word is written: any value, unused)
  end

  always @(posedge clk) begin
    ok_d_reg      <= ok_reg;
    asked_now_reg <= (state_reg == IDLE) && !go;
    if (state_reg == IDLE) begin
      if (go) begin
        lo_reg    <= word_reg;
        state_reg <= READ_HI;
      end else begin
        asked_reg <= quarter;
        dirty_reg <= 1'b0;
      end
    end else begin   // READ_HI
      if (!dirty_reg) begin
        c_lo_reg <= lo_reg;
        c_hi_reg <= word_reg;
        pair_reg <= asked_reg;
        ok_reg   <= 1'b1;
      end
      state_reg <= IDLE;
    end
    if (write) begin
      dirty_reg <= 1'b1;
      ok_reg    <= 1'b0;
    end
    if (rst) begin
      state_reg     <= IDLE;
      asked_now_reg <= 1'b0;
      ok_d_reg      <= 1'b0;
      ok_reg        <= 1'b0;
    end
  end

  assign c_lo         = c_lo_reg;
  assign c_hi         = c_hi_reg;
  assign pair_quarter = pair_reg;
  assign ok           = ok_reg;

endmodule

`resetall
