// SPDX-License-Identifier: Apache-2.0
// prenc_rom_check: simulation-time check of a $readmemh table file.
//
// A missing table file must not become an all-X or all-zero ROM. This module opens
// FILE, then loads it into a one-bit-wider copy preset to a marker value that no
// WIDTH-bit word can have; a marker left over is a word the file did not supply (a
// short file, or a word wider than WIDTH). Either stops the simulation at time 0
// with a message naming the instance and NAME (the owner's parameter). It has no
// ports and no hardware: the owner instantiates it under `ifndef SYNTHESIS (Yosys
// stops by itself on a missing file).
//
// Latency: none; the module has no ports and only checks the table file while it is
// elaborated and at time 0 of a simulation.
//
// Parameters
//   NAME   the owner's parameter that names the file, for the message
//   FILE   the $readmemh file
//   DEPTH  words the file must supply, 1..2^24
//   WIDTH  bits per word, 1..128

// Guarded: more than one block's file list names it (the converter's, the calibration
// table's), and a top's list may include both.

`resetall
`timescale 1ns / 1ps
`default_nettype none
`ifndef PRENC_ROM_CHECK_V
`define PRENC_ROM_CHECK_V

module prenc_rom_check #(
  parameter         NAME  = "ROM_FILE",
  parameter         FILE  = "rom.hex",
  parameter integer DEPTH = 16,
  parameter integer WIDTH = 4
);

  reg     [WIDTH:0] words [0:DEPTH-1];
  integer           fd;
  integer           i;
  integer           missing;

  initial begin
    fd = $fopen(FILE, "r");
    if (fd == 0) begin
      $display("ERROR: %m: %0s \"%0s\" cannot be opened", NAME, FILE);
      $finish;
    end else begin
      $fclose(fd);
      for (i = 0; i < DEPTH; i = i + 1) begin
        words[i] = {1'b1, {WIDTH{1'b0}}};
      end
      $readmemh(FILE, words);
      missing = 0;
      for (i = 0; i < DEPTH; i = i + 1) begin
        if (words[i][WIDTH]) begin
          missing = missing + 1;
        end
      end
      if (missing != 0) begin
        $display("ERROR: %m: %0s \"%0s\": %0d of %0d words missing or wider than %0d bits",
                 NAME, FILE, missing, DEPTH, WIDTH);
        $finish;
      end
    end
  end

endmodule

`endif  // PRENC_ROM_CHECK_V
`resetall
