// SPDX-License-Identifier: Apache-2.0
// prenc_matrix_fkm: the FKM de Bruijn sequence, one symbol per clock, in hardware.
//
// Emits the lexicographically least de Bruijn sequence of order N over 2^B symbols
// (the Lyndon words whose length divides N, in lexicographic order), the same
// sequence as prenc.matrix.code.fkm. It runs Ruskey's prenecklace step: find the last
// symbol a[i] that is not 2^B - 1, increment it, fill a[i+1..N-1] periodically from
// a[0..i]; when N is a multiple of p = i + 1, emit a[0..p-1], one symbol per clock.
// Each step without output costs one clock, so the 2^(N*B) symbols take 2^(N*B) +
// (number of prenecklaces) clocks: 83,948 clocks for N = 4, B = 4.
//
// Latency: the first symbol a few clocks after reset; then one symbol per clock, and
// one clock more for each step without output: 2^(N*B) + (number of prenecklaces)
// clocks in all.
//
// Parameters: N 2..4 (order), B 1..4 (bits per symbol).
// Ports
//   clk, rst   starts again from the first symbol on reset
//   sym_valid  sym holds the next symbol of the sequence (one clock each)
//   sym        the symbol
//   done       high from the clock after the last symbol, until reset

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_matrix_fkm #(
  parameter integer N = 4,
  parameter integer B = 4
) (
  input  wire         clk,
  input  wire         rst,
  output reg          sym_valid,
  output reg  [B-1:0] sym,
  output reg          done
);

  generate
    if (N < 2 || N > 4) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..4", N);
      prenc_matrix_fkm_parameter_N_out_of_range_2_to_4 u_stop ();
    end
    if (B < 1 || B > 4) begin : g_bad_b
      initial $display("ERROR: %m: parameter B = %0d is out of range 1..4", B);
      prenc_matrix_fkm_parameter_B_out_of_range_1_to_4 u_stop ();
    end
  endgenerate

  localparam [B-1:0] TOP = {B{1'b1}};

  // a[j] is word_reg[j*B +: B]; p and the emit index count from 0.
  reg [N*B-1:0] word_reg;
  reg [N*B-1:0] word_next;
  reg [2:0]     len_reg;           // p, the length of the Lyndon prefix, 1..N
  reg [2:0]     len_next;
  reg [2:0]     idx_reg;           // symbol of a[0..p-1] emitted next
  reg [2:0]     idx_next;
  reg           emit_reg;          // emitting a[0..p-1]; else stepping
  reg           emit_next;
  reg           done_next;
  reg           sym_valid_next;
  reg [B-1:0]   sym_next;

  // The step: i = the last index with a[i] != TOP (found = some exists).
  reg [2:0]     last;
  reg           found;
  reg [2:0]     period;            // i + 1
  reg [B-1:0]   bumped;            // a[i] + 1
  reg           divides;           // N is a multiple of period
  reg [2:0]     src;               // j mod period
  integer       j;                 // loop index of the search
  integer       k;                 // loop index of the fill
  integer       q;

  always @* begin
    divides = 1'b0;
    for (q = 1; q <= N; q = q + 1) begin
      if (period == q[2:0] && (N % q) == 0) begin
        divides = 1'b1;
      end
    end
  end

  always @* begin
    found = 1'b0;
    last  = 3'd0;
    for (j = 0; j < N; j = j + 1) begin
      if (word_reg[j*B +: B] != TOP) begin
        found = 1'b1;
        last  = j[2:0];
      end
    end
    period = last + 3'd1;
    bumped = word_reg[last*B +: B] + {{(B-1){1'b0}}, 1'b1};
  end

  always @* begin
    word_next      = word_reg;
    len_next       = len_reg;
    idx_next       = idx_reg;
    emit_next      = emit_reg;
    done_next      = done;
    sym_valid_next = 1'b0;
    sym_next       = sym;
    src            = 3'd0;
    k              = 0;

    if (!done) begin
      if (emit_reg) begin
        sym_valid_next = 1'b1;
        sym_next       = word_reg[idx_reg*B +: B];
        idx_next       = idx_reg + 3'd1;
        if (idx_reg + 3'd1 == len_reg) begin
          emit_next = 1'b0;
        end
      end else if (!found) begin
        done_next = 1'b1;
      end else begin
        for (k = 0; k < N; k = k + 1) begin
          // a[k] = a'[k mod p], a' = a with a[i] incremented (j mod p <= i);
          // k < 4, so three conditional subtractions reduce it
          src = k[2:0];
          if (src >= period) src = src - period;
          if (src >= period) src = src - period;
          if (src >= period) src = src - period;
          if (src == last) begin
            word_next[k*B +: B] = bumped;
          end else begin
            word_next[k*B +: B] = word_reg[src*B +: B];
          end
        end
        len_next = period;
        idx_next = 3'd0;
        if (divides) begin
          emit_next = 1'b1;
        end
      end
    end
  end

  always @(posedge clk) begin
    word_reg  <= word_next;
    len_reg   <= len_next;
    idx_reg   <= idx_next;
    emit_reg  <= emit_next;
    done      <= done_next;
    sym_valid <= sym_valid_next;
    sym       <= sym_next;
    if (rst) begin
      word_reg  <= {(N*B){1'b0}};
      len_reg   <= 3'd1;
      idx_reg   <= 3'd0;
      emit_reg  <= 1'b1;
      done      <= 1'b0;
      sym_valid <= 1'b0;
      sym       <= {B{1'b0}};
    end
  end

endmodule

`resetall
