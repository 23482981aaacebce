// SPDX-License-Identifier: Apache-2.0
// prenc_matrix_table: window address -> position, for a matrix code.
//
// The table of `prenc matrix rom`: address = the window's A data bits (first column
// most significant, track 0 the MSB of a column; with the parity track, its bit is
// left out), data = the position, A bits. Registered read: rd_data holds the
// position of the address presented with rd_en one clock earlier.
//
// Two sources for the table (parameter TABLE):
//   "file"       a ROM initialised from TABLE_FILE ($readmemh, 2^A words). Maps to
//                block RAM; a missing or short file stops simulation at time 0.
//   "generator"  a RAM that fills itself after reset: prenc_matrix_fkm emits the
//                code's symbols and the table stores, for each window, its
//                position. The RAM has one address port and no initial contents,
//                so Yosys (synth_ice40 -spram) maps the 64 Ki x 16 table of N = 4
//                to the four SB_SPRAM256KA of an iCE40 UP5K, which no bitstream
//                can preload. ready rises after 2^A + (prenecklaces) + N + 1
//                clocks (83,953 for N = 4); reads before ready return garbage.
//
// Latency: one clock (registered read); with TABLE = "generator", reads are meaningful
// once `ready` is high.
//
// Parameters
//   N           order, 2..4 (an N x N window)
//   CHECKSUM    1: track N-1 is the even parity of the others (N-1 data bits a column)
//   TABLE       "file" or "generator"
//   TABLE_FILE  for "file": `prenc matrix rom --n N [--checksum] --format hex`
//
// Ports: clk, rst (synchronous; "generator" builds the table again), ready,
//        rd_en, rd_addr, rd_data.

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_matrix_table #(
  parameter integer N          = 4,
  parameter integer CHECKSUM   = 0,
  parameter [71:0]  TABLE      = "file",
  parameter         TABLE_FILE = "prenc_matrix_n4.hex",
  // derived; do not override
  parameter integer A          = N * (N - CHECKSUM)
) (
  input  wire         clk,
  input  wire         rst,
  output reg          ready,
  input  wire         rd_en,
  input  wire [A-1:0] rd_addr,
  output reg  [A-1:0] rd_data
);

  localparam integer B     = N - CHECKSUM;     // data bits per column
  localparam integer DEPTH = 1 << A;
  localparam [31:0]  FIRST = N - 1;            // symbols before the first whole window

  generate
    if (N < 2 || N > 4) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..4", N);
      prenc_matrix_table_parameter_N_out_of_range_2_to_4 u_stop ();
    end
    if (CHECKSUM < 0 || CHECKSUM > 1) begin : g_bad_checksum
      initial $display("ERROR: %m: parameter CHECKSUM = %0d is not 0 or 1", CHECKSUM);
      prenc_matrix_table_parameter_CHECKSUM_not_0_or_1 u_stop ();
    end
    if (TABLE != "file" && TABLE != "generator") begin : g_bad_table
      initial $display("ERROR: %m: parameter TABLE = \"%0s\" is not \"file\" or \"generator\"",
                       TABLE);
      prenc_matrix_table_parameter_TABLE_not_file_or_generator u_stop ();
    end
  endgenerate

  reg [A-1:0] mem [0:DEPTH-1];

  generate
    if (TABLE == "file") begin : g_file
      initial $readmemh(TABLE_FILE, mem);

      always @(posedge clk) begin
        if (rd_en) begin
          rd_data <= mem[rd_addr];
        end
      end

      always @(posedge clk) begin
        ready <= 1'b1;
        if (rst) begin
          ready <= 1'b0;
        end
      end

`ifndef SYNTHESIS
      prenc_rom_check #(
        .NAME  ("TABLE_FILE"),
        .FILE  (TABLE_FILE),
        .DEPTH (DEPTH),
        .WIDTH (A)
      ) u_rom_check ();
`endif
    end else begin : g_generator
      // The code's first N-1 symbols are zeros (FKM starts with N zeros), so after
      // the generator's last symbol N-1 zeros close the cycle's last windows.
      wire         sym_valid;
      wire [B-1:0] sym;
      wire         sym_done;
      reg  [A-B-1:0] window_reg;     // the last N-1 symbols, newest in the low bits
      reg  [A:0]   count_reg;        // symbols taken so far
      reg  [2:0]   tail_reg;         // closing zeros still to feed
      reg          take;
      reg  [B-1:0] take_sym;
      reg  [A-1:0] window_next;
      reg          we;
      reg  [A-1:0] wr_pos;
      wire [A-1:0] addr = we ? window_next : rd_addr;

      prenc_matrix_fkm #(
        .N (N),
        .B (B)
      ) u_fkm (
        .clk       (clk),
        .rst       (rst),
        .sym_valid (sym_valid),
        .sym       (sym),
        .done      (sym_done)
      );

      always @* begin
        take     = sym_valid || (sym_done && tail_reg != 3'd0);
        take_sym = sym_valid ? sym : {B{1'b0}};
        window_next = {window_reg, take_sym};
        we          = take && count_reg >= FIRST[A:0];
        wr_pos      = count_reg[A-1:0] - FIRST[A-1:0];
      end

      always @(posedge clk) begin
        if (we) begin
          mem[addr] <= wr_pos;
        end else if (rd_en) begin
          rd_data <= mem[addr];
        end
      end

      always @(posedge clk) begin
        if (take) begin
          window_reg <= window_next[A-B-1:0];
          count_reg  <= count_reg + 1'b1;
        end
        if (sym_done && !sym_valid && tail_reg != 3'd0) begin
          tail_reg <= tail_reg - 3'd1;
        end
        if (sym_done && tail_reg == 3'd0) begin
          ready <= 1'b1;
        end
        if (rst) begin
          window_reg <= {(A-B){1'b0}};
          count_reg  <= {(A+1){1'b0}};
          tail_reg   <= FIRST[2:0];
          ready      <= 1'b0;
        end
      end
    end
  endgenerate

endmodule

`resetall
