// SPDX-License-Identifier: Apache-2.0
// DP16KD, the ECP5's 18-kbit block RAM, for simulating Yosys's ECP5 netlists
// (tb/board/netlist). Yosys ships this cell only as a black box; this model follows
// Lattice's ECP5 memory usage guide (FPGA-TN-02204) for the modes the boards' netlists
// use, and stops the simulation on any other:
//   - DATA_WIDTH_A/B 18 (1,024 words: address ADx[13:4], byte enables ADx[1:0] on
//     writes) and 9 (2,048 words: address ADx[13:3]);
//   - both 36, the pseudo-dual-port mode Yosys's brams_map_16kd.v makes of a wide
//     ROM (512 words: port B reads at ADB[13:5], the word's low 18 bits on DOA and its
//     high 18 on DOB; each word is two 18-bit entries of the INITVALs, low first);
//     port A would write it, which is not modelled: a write stops the simulation;
//   - WRITEMODE NORMAL (the output holds on a write), WRITETHROUGH (shows the new
//     word), READBEFOREWRITE (shows the old one);
//   - REGMODE NOREG (the word read shows after the clock) and OUTREG (one clock more,
//     enabled by OCEx); RESETMODE SYNC or ASYNC (RSTx clears the output);
//   - CSDECODE_x: the port works when CSx[2:0] equals it;
//   - INITVAL_00..3F: 16 words of 20 bits each, a word's 18 data bits in its low bits
//     (the layout Yosys's brams_map_16kd.v writes; the 2 high bits unused);
//   - the clock muxes as "CLKx" only (no inverted clock); GSR is not modelled.
// The outputs start at 0, as a configured device's.
//
// Latency: DOx shows a read 1 clock after it (NOREG) or 2 (OUTREG).

`resetall
`timescale 1ns / 1ps
`default_nettype none

module DP16KD (
  input  wire DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9,
  input  wire DIA8, DIA7, DIA6, DIA5, DIA4, DIA3, DIA2, DIA1, DIA0,
  input  wire ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4,
  input  wire ADA3, ADA2, ADA1, ADA0,
  input  wire CEA, OCEA, CLKA, WEA, RSTA,
  input  wire CSA2, CSA1, CSA0,
  output wire DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9,
  output wire DOA8, DOA7, DOA6, DOA5, DOA4, DOA3, DOA2, DOA1, DOA0,
  input  wire DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9,
  input  wire DIB8, DIB7, DIB6, DIB5, DIB4, DIB3, DIB2, DIB1, DIB0,
  input  wire ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4,
  input  wire ADB3, ADB2, ADB1, ADB0,
  input  wire CEB, OCEB, CLKB, WEB, RSTB,
  input  wire CSB2, CSB1, CSB0,
  output wire DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9,
  output wire DOB8, DOB7, DOB6, DOB5, DOB4, DOB3, DOB2, DOB1, DOB0
);
  parameter DATA_WIDTH_A = 18;
  parameter DATA_WIDTH_B = 18;
  parameter REGMODE_A = "NOREG";
  parameter REGMODE_B = "NOREG";
  parameter RESETMODE = "SYNC";
  parameter ASYNC_RESET_RELEASE = "SYNC";
  parameter CSDECODE_A = "0b000";
  parameter CSDECODE_B = "0b000";
  parameter WRITEMODE_A = "NORMAL";
  parameter WRITEMODE_B = "NORMAL";
  parameter GSR = "ENABLED";
  parameter CLKAMUX = "CLKA";
  parameter CLKBMUX = "CLKB";
  parameter INIT_DATA = "STATIC";
  parameter [319:0] INITVAL_00 = 320'h0;
  parameter [319:0] INITVAL_01 = 320'h0;
  parameter [319:0] INITVAL_02 = 320'h0;
  parameter [319:0] INITVAL_03 = 320'h0;
  parameter [319:0] INITVAL_04 = 320'h0;
  parameter [319:0] INITVAL_05 = 320'h0;
  parameter [319:0] INITVAL_06 = 320'h0;
  parameter [319:0] INITVAL_07 = 320'h0;
  parameter [319:0] INITVAL_08 = 320'h0;
  parameter [319:0] INITVAL_09 = 320'h0;
  parameter [319:0] INITVAL_0A = 320'h0;
  parameter [319:0] INITVAL_0B = 320'h0;
  parameter [319:0] INITVAL_0C = 320'h0;
  parameter [319:0] INITVAL_0D = 320'h0;
  parameter [319:0] INITVAL_0E = 320'h0;
  parameter [319:0] INITVAL_0F = 320'h0;
  parameter [319:0] INITVAL_10 = 320'h0;
  parameter [319:0] INITVAL_11 = 320'h0;
  parameter [319:0] INITVAL_12 = 320'h0;
  parameter [319:0] INITVAL_13 = 320'h0;
  parameter [319:0] INITVAL_14 = 320'h0;
  parameter [319:0] INITVAL_15 = 320'h0;
  parameter [319:0] INITVAL_16 = 320'h0;
  parameter [319:0] INITVAL_17 = 320'h0;
  parameter [319:0] INITVAL_18 = 320'h0;
  parameter [319:0] INITVAL_19 = 320'h0;
  parameter [319:0] INITVAL_1A = 320'h0;
  parameter [319:0] INITVAL_1B = 320'h0;
  parameter [319:0] INITVAL_1C = 320'h0;
  parameter [319:0] INITVAL_1D = 320'h0;
  parameter [319:0] INITVAL_1E = 320'h0;
  parameter [319:0] INITVAL_1F = 320'h0;
  parameter [319:0] INITVAL_20 = 320'h0;
  parameter [319:0] INITVAL_21 = 320'h0;
  parameter [319:0] INITVAL_22 = 320'h0;
  parameter [319:0] INITVAL_23 = 320'h0;
  parameter [319:0] INITVAL_24 = 320'h0;
  parameter [319:0] INITVAL_25 = 320'h0;
  parameter [319:0] INITVAL_26 = 320'h0;
  parameter [319:0] INITVAL_27 = 320'h0;
  parameter [319:0] INITVAL_28 = 320'h0;
  parameter [319:0] INITVAL_29 = 320'h0;
  parameter [319:0] INITVAL_2A = 320'h0;
  parameter [319:0] INITVAL_2B = 320'h0;
  parameter [319:0] INITVAL_2C = 320'h0;
  parameter [319:0] INITVAL_2D = 320'h0;
  parameter [319:0] INITVAL_2E = 320'h0;
  parameter [319:0] INITVAL_2F = 320'h0;
  parameter [319:0] INITVAL_30 = 320'h0;
  parameter [319:0] INITVAL_31 = 320'h0;
  parameter [319:0] INITVAL_32 = 320'h0;
  parameter [319:0] INITVAL_33 = 320'h0;
  parameter [319:0] INITVAL_34 = 320'h0;
  parameter [319:0] INITVAL_35 = 320'h0;
  parameter [319:0] INITVAL_36 = 320'h0;
  parameter [319:0] INITVAL_37 = 320'h0;
  parameter [319:0] INITVAL_38 = 320'h0;
  parameter [319:0] INITVAL_39 = 320'h0;
  parameter [319:0] INITVAL_3A = 320'h0;
  parameter [319:0] INITVAL_3B = 320'h0;
  parameter [319:0] INITVAL_3C = 320'h0;
  parameter [319:0] INITVAL_3D = 320'h0;
  parameter [319:0] INITVAL_3E = 320'h0;
  parameter [319:0] INITVAL_3F = 320'h0;

  function [319:0] initval;
    input [7:0] row;
    case (row)
      8'h00: initval = INITVAL_00;
      8'h01: initval = INITVAL_01;
      8'h02: initval = INITVAL_02;
      8'h03: initval = INITVAL_03;
      8'h04: initval = INITVAL_04;
      8'h05: initval = INITVAL_05;
      8'h06: initval = INITVAL_06;
      8'h07: initval = INITVAL_07;
      8'h08: initval = INITVAL_08;
      8'h09: initval = INITVAL_09;
      8'h0A: initval = INITVAL_0A;
      8'h0B: initval = INITVAL_0B;
      8'h0C: initval = INITVAL_0C;
      8'h0D: initval = INITVAL_0D;
      8'h0E: initval = INITVAL_0E;
      8'h0F: initval = INITVAL_0F;
      8'h10: initval = INITVAL_10;
      8'h11: initval = INITVAL_11;
      8'h12: initval = INITVAL_12;
      8'h13: initval = INITVAL_13;
      8'h14: initval = INITVAL_14;
      8'h15: initval = INITVAL_15;
      8'h16: initval = INITVAL_16;
      8'h17: initval = INITVAL_17;
      8'h18: initval = INITVAL_18;
      8'h19: initval = INITVAL_19;
      8'h1A: initval = INITVAL_1A;
      8'h1B: initval = INITVAL_1B;
      8'h1C: initval = INITVAL_1C;
      8'h1D: initval = INITVAL_1D;
      8'h1E: initval = INITVAL_1E;
      8'h1F: initval = INITVAL_1F;
      8'h20: initval = INITVAL_20;
      8'h21: initval = INITVAL_21;
      8'h22: initval = INITVAL_22;
      8'h23: initval = INITVAL_23;
      8'h24: initval = INITVAL_24;
      8'h25: initval = INITVAL_25;
      8'h26: initval = INITVAL_26;
      8'h27: initval = INITVAL_27;
      8'h28: initval = INITVAL_28;
      8'h29: initval = INITVAL_29;
      8'h2A: initval = INITVAL_2A;
      8'h2B: initval = INITVAL_2B;
      8'h2C: initval = INITVAL_2C;
      8'h2D: initval = INITVAL_2D;
      8'h2E: initval = INITVAL_2E;
      8'h2F: initval = INITVAL_2F;
      8'h30: initval = INITVAL_30;
      8'h31: initval = INITVAL_31;
      8'h32: initval = INITVAL_32;
      8'h33: initval = INITVAL_33;
      8'h34: initval = INITVAL_34;
      8'h35: initval = INITVAL_35;
      8'h36: initval = INITVAL_36;
      8'h37: initval = INITVAL_37;
      8'h38: initval = INITVAL_38;
      8'h39: initval = INITVAL_39;
      8'h3A: initval = INITVAL_3A;
      8'h3B: initval = INITVAL_3B;
      8'h3C: initval = INITVAL_3C;
      8'h3D: initval = INITVAL_3D;
      8'h3E: initval = INITVAL_3E;
      8'h3F: initval = INITVAL_3F;
      default: initval = 320'h0;
    endcase
  endfunction

  // "0bXYZ" -> 3'bXYZ: each character's low bit is its binary digit.
  function [2:0] cs_decode;
    input [39:0] text;
    cs_decode = {text[16], text[8], text[0]};
  endfunction

  reg [17:0] mem [0:1023];
  integer row, word;
  localparam WIDE = (DATA_WIDTH_A == 36) && (DATA_WIDTH_B == 36);
  initial begin
    if (DATA_WIDTH_A != 18 && DATA_WIDTH_A != 9 && !WIDE) begin
      $display("ERROR: %m: DP16KD model: DATA_WIDTH_A = %0d is not modelled (18, 9; 36 with B)",
               DATA_WIDTH_A);
      $finish(1);
    end
    if (DATA_WIDTH_B != 18 && DATA_WIDTH_B != 9 && !WIDE) begin
      $display("ERROR: %m: DP16KD model: DATA_WIDTH_B = %0d is not modelled (18, 9; 36 with A)",
               DATA_WIDTH_B);
      $finish(1);
    end
    if (CLKAMUX != "CLKA" || CLKBMUX != "CLKB") begin
      $display("ERROR: %m: DP16KD model: an inverted clock is not modelled");
      $finish(1);
    end
    for (row = 0; row < 64; row = row + 1)
      for (word = 0; word < 16; word = word + 1)
        mem[row * 16 + word] = initval(row[7:0]) >> (word * 20);
  end

  wire [17:0] dia = {DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9,
                     DIA8, DIA7, DIA6, DIA5, DIA4, DIA3, DIA2, DIA1, DIA0};
  wire [17:0] dib = {DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9,
                     DIB8, DIB7, DIB6, DIB5, DIB4, DIB3, DIB2, DIB1, DIB0};
  wire [13:0] ada = {ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4,
                     ADA3, ADA2, ADA1, ADA0};
  wire [13:0] adb = {ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4,
                     ADB3, ADB2, ADB1, ADB0};

  wire [17:0] doa;
  wire [17:0] dob;
  assign {DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9,
          DOA8, DOA7, DOA6, DOA5, DOA4, DOA3, DOA2, DOA1, DOA0} = doa;
  assign {DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9,
          DOB8, DOB7, DOB6, DOB5, DOB4, DOB3, DOB2, DOB1, DOB0} = dob;

  // Port A.
  wire        ce_a   = CEA & (cs_decode(CSDECODE_A) == {CSA2, CSA1, CSA0});
  wire [9:0]  row_a  = ada[13:4];
  wire [17:0] old_a  = mem[row_a];
  wire [17:0] read_a = (DATA_WIDTH_A == 18) ? old_a
                       : {9'd0, ada[3] ? old_a[17:9] : old_a[8:0]};
  wire [17:0] new_a  = (DATA_WIDTH_A == 18)
                       ? {ada[1] ? dia[17:9] : old_a[17:9], ada[0] ? dia[8:0] : old_a[8:0]}
                       : (ada[3] ? {dia[8:0], old_a[8:0]} : {old_a[17:9], dia[8:0]});
  reg  [17:0] latch_a;
  reg  [17:0] out_a;
  initial latch_a = 18'd0;
  initial out_a   = 18'd0;

  // RESETMODE ASYNC: RSTA clears the outputs at once; SYNC: at a clock, with CEA.
  wire arst_a = (RESETMODE == "ASYNC") & RSTA;

  always @(posedge CLKA or posedge arst_a) begin
    if (arst_a) begin
      latch_a <= 18'd0;
    end else if (ce_a && RSTA) begin
      latch_a <= 18'd0;
    end else if (ce_a) begin
      if (WEA) begin
        mem[row_a] <= new_a;
        if (WRITEMODE_A == "WRITETHROUGH")
          latch_a <= (DATA_WIDTH_A == 18) ? new_a : {9'd0, dia[8:0]};
        else if (WRITEMODE_A == "READBEFOREWRITE")
          latch_a <= read_a;
      end else begin
        latch_a <= read_a;
      end
    end
  end

  always @(posedge CLKA or posedge arst_a) begin
    if (arst_a || RSTA) out_a <= 18'd0;
    else if (OCEA) out_a <= latch_a;
  end


  // Port B.
  wire        ce_b   = CEB & (cs_decode(CSDECODE_B) == {CSB2, CSB1, CSB0});
  wire [9:0]  row_b  = adb[13:4];
  wire [17:0] old_b  = mem[row_b];
  wire [17:0] read_b = (DATA_WIDTH_B == 18) ? old_b
                       : {9'd0, adb[3] ? old_b[17:9] : old_b[8:0]};
  wire [17:0] new_b  = (DATA_WIDTH_B == 18)
                       ? {adb[1] ? dib[17:9] : old_b[17:9], adb[0] ? dib[8:0] : old_b[8:0]}
                       : (adb[3] ? {dib[8:0], old_b[8:0]} : {old_b[17:9], dib[8:0]});
  reg  [17:0] latch_b;
  reg  [17:0] out_b;
  initial latch_b = 18'd0;
  initial out_b   = 18'd0;

  // RESETMODE ASYNC: RSTB clears the outputs at once; SYNC: at a clock, with CEB.
  wire arst_b = (RESETMODE == "ASYNC") & RSTB;

  always @(posedge CLKB or posedge arst_b) begin
    if (arst_b) begin
      latch_b <= 18'd0;
    end else if (ce_b && RSTB) begin
      latch_b <= 18'd0;
    end else if (ce_b) begin
      if (WEB) begin
        mem[row_b] <= new_b;
        if (WRITEMODE_B == "WRITETHROUGH")
          latch_b <= (DATA_WIDTH_B == 18) ? new_b : {9'd0, dib[8:0]};
        else if (WRITEMODE_B == "READBEFOREWRITE")
          latch_b <= read_b;
      end else begin
        latch_b <= read_b;
      end
    end
  end

  always @(posedge CLKB or posedge arst_b) begin
    if (arst_b || RSTB) out_b <= 18'd0;
    else if (OCEB) out_b <= latch_b;
  end

  // The 36-bit mode: port B reads both halves of a word; port A is a ROM's (no writes).
  wire [8:0]  word_w  = adb[13:5];
  reg  [35:0] latch_w;
  reg  [35:0] out_w;
  initial latch_w = 36'd0;
  initial out_w   = 36'd0;

  always @(posedge CLKB or posedge arst_b) begin
    if (arst_b) latch_w <= 36'd0;
    else if (ce_b && RSTB) latch_w <= 36'd0;
    else if (ce_b) latch_w <= {mem[{word_w, 1'b1}], mem[{word_w, 1'b0}]};
  end

  always @(posedge CLKB or posedge arst_b) begin
    if (arst_b || RSTB) out_w <= 36'd0;
    else if (OCEB) out_w <= latch_w;
  end

  always @(posedge CLKA) begin
    if (WIDE && ce_a && WEA && (ada[3:0] != 4'd0)) begin
      $display("ERROR: %m: DP16KD model: a write in the 36-bit mode is not modelled");
      $finish(1);
    end
  end

  wire [35:0] wide_out = (REGMODE_B == "OUTREG") ? out_w : latch_w;
  assign doa = WIDE ? wide_out[17:0] : (REGMODE_A == "OUTREG") ? out_a : latch_a;
  assign dob = WIDE ? wide_out[35:18] : (REGMODE_B == "OUTREG") ? out_b : latch_b;

endmodule

`resetall
