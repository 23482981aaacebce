// SPDX-License-Identifier: Apache-2.0
// prenc_velocity_program: prenc_velocity's program in block RAM, a word a clock:
// {step, invert, mul, load, op[3:0], special, abortable, a[4:0], n[7:0], next_s,
// next_a[4:0]} (prenc.fine.engine, prenc.fine.program; docs/fine.md). step, invert,
// mul, load: the adder's controls, decoded here (DIV or MUL; SUB or DIV; MUL; LOAD).
// next_s, next_a: the operand of the instruction after it in the program (a special
// and its number, or the register file's address).
//
// Latency: word is the instruction at pc of the clock before (one clock).
//
// Written by `python -m prenc.fine.program` from sim/prenc/fine/program.py; do not edit.
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_velocity_program (
  input  wire        clk,
  input  wire [7:0]  pc,
  output reg  [28:0] word,      // the word at pc, a clock later
  output wire [7:0]  restart    // where a restart goes
);

  reg [28:0] rom [0:255];

  assign restart = 8'd209;

  integer i;
  initial begin
    for (i = 0; i < 256; i = i + 1) rom[i] = 29'd0;
    rom[0] = 29'h1a04a00;   // IDLE: JMP PEND STEP
    rom[1] = 29'h1a10240;   // JMP HAVE AGE
    rom[2] = 29'h1a1c020;   // JMP NOT_ANCH IDLE
    rom[3] = 29'h230000a;   // LOAD s.NOW
    rom[4] = 29'h8628007;   // SUB W_TIME
    rom[5] = 29'h861c000;   // SUB C_OLD
    rom[6] = 29'h1a08000;   // JMP NEG IDLE
    rom[7] = 29'h1600000;   // FLAG ANCH 0
    rom[8] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[9] = 29'h0000020;   // AGE: NOP
    rom[10] = 29'h2300024;   // LOAD s.NOW
    rom[11] = 29'h8710000;   // SUB s.LTIME
    rom[12] = 29'h1250000;   // STORE T1
    rom[13] = 29'h1a24415;   // JMP NOT_BND BOUND
    rom[14] = 29'h8654000;   // SUB STOP_AT
    rom[15] = 29'h1a0c840;   // JMP NOT_NEG STOP
    rom[16] = 29'h0000025;   // BOUND: NOP
    rom[17] = 29'h2314004;   // LOAD s.LWIDTH
    rom[18] = 29'h0410000;   // ADD C_LEVEL0
    rom[19] = 29'h0a00014;   // NUM
    rom[20] = 29'h18cd0d00;   // DIV T1 52 abortable
    rom[21] = 29'h1000023;   // QUOT
    rom[22] = 29'h870c000;   // SUB s.SPEED
    rom[23] = 29'h1a0c023;   // JMP NOT_NEG IDLE
    rom[24] = 29'h050c000;   // ADD s.SPEED
    rom[25] = 29'h1400000;   // OUT SPEED_A0
    rom[26] = 29'h1a20000;   // JMP BND IDLE
    rom[27] = 29'h1608054;   // FLAG BND 1
    rom[28] = 29'h2250000;   // LOAD T1
    rom[29] = 29'h0800054;   // HALF 1
    rom[30] = 29'h0450000;   // ADD T1
    rom[31] = 29'h1254000;   // STORE STOP_AT
    rom[32] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[33] = 29'h0000000;   // STOP: NOP
    rom[34] = 29'h2200000;   // LOAD C_ZERO
    rom[35] = 29'h1400000;   // OUT SPEED_A0
    rom[36] = 29'h1600000;   // FLAG ANCH 0
    rom[37] = 29'h1604000;   // FLAG HAVE 0
    rom[38] = 29'h1608000;   // FLAG BND 0
    rom[39] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[40] = 29'h1608000;   // STEP: FLAG BND 0
    rom[41] = 29'h1a1f221;   // JMP NOT_ANCH ANCHOR
    rom[42] = 29'h230400a;   // LOAD s.STIME
    rom[43] = 29'h8628000;   // SUB W_TIME
    rom[44] = 29'h1244002;   // STORE P1
    rom[45] = 29'h8608000;   // SUB C_SHORT
    rom[46] = 29'h1a0b3e2;   // JMP NEG DONE
    rom[47] = 29'h230800b;   // LOAD s.SPOSC
    rom[48] = 29'h862c000;   // SUB W_POSC
    rom[49] = 29'h1250000;   // STORE T1
    rom[50] = 29'h1a0b203;   // JMP NEG ANCHOR
    rom[51] = 29'h860c000;   // SUB C_QUARTERS
    rom[52] = 29'h1a08e11;   // JMP NEG CLOSE
    rom[53] = 29'h2244001;   // LOAD P1
    rom[54] = 29'h8604000;   // SUB C_WINDOW
    rom[55] = 29'h1a0b3c0;   // JMP NEG DONE
    rom[56] = 29'h0000021;   // CLOSE: NOP
    rom[57] = 29'h2304000;   // LOAD s.STIME
    rom[58] = 29'h1228022;   // STORE W_TIME
    rom[59] = 29'h2308000;   // LOAD s.SPOSC
    rom[60] = 29'h122c014;   // STORE W_POSC
    rom[61] = 29'h2250000;   // LOAD T1
    rom[62] = 29'h0a00011;   // NUM
    rom[63] = 29'h18c44d00;   // DIV P1 52
    rom[64] = 29'h1000000;   // QUOT
    rom[65] = 29'h1230000;   // STORE V1
    rom[66] = 29'h1a16de3;   // JMP NOT_HAVE FIRST
    rom[67] = 29'h230c005;   // LOAD s.SPEED
    rom[68] = 29'h0414000;   // ADD C_2DELTA
    rom[69] = 29'h0a00011;   // NUM
    rom[70] = 29'h18c44800;   // DIV P1 32
    rom[71] = 29'h1000000;   // QUOT
    rom[72] = 29'h124c00c;   // STORE T0
    rom[73] = 29'h2230023;   // LOAD V1
    rom[74] = 29'h870c000;   // SUB s.SPEED
    rom[75] = 29'h0800040;   // HALF 1
    rom[76] = 29'h1a09413;   // JMP NEG BELOW
    rom[77] = 29'h864c000;   // SUB T0
    rom[78] = 29'h1a09900;   // JMP NEG CONSTANT
    rom[79] = 29'h1a014c0;   // JMP ALWAYS AGREE
    rom[80] = 29'h0000013;   // BELOW: NOP
    rom[81] = 29'h044c000;   // ADD T0
    rom[82] = 29'h1a0d900;   // JMP NOT_NEG CONSTANT
    rom[83] = 29'h000000c;   // AGREE: NOP
    rom[84] = 29'h223000d;   // LOAD V1
    rom[85] = 29'h8634000;   // SUB V2
    rom[86] = 29'h0800040;   // HALF 1
    rom[87] = 29'h1a096d3;   // JMP NEG BELOW_V2
    rom[88] = 29'h864c000;   // SUB T0
    rom[89] = 29'h1a0dbc0;   // JMP NOT_NEG FIT
    rom[90] = 29'h1a01780;   // JMP ALWAYS AGREED
    rom[91] = 29'h0000013;   // BELOW_V2: NOP
    rom[92] = 29'h044c000;   // ADD T0
    rom[93] = 29'h1a09bc0;   // JMP NEG FIT
    rom[94] = 29'h000000c;   // AGREED: NOP
    rom[95] = 29'h223000d;   // LOAD V1
    rom[96] = 29'h0434000;   // ADD V2
    rom[97] = 29'h0800040;   // HALF 1
    rom[98] = 29'h1400000;   // OUT SPEED_A0
    rom[99] = 29'h1a01a80;   // JMP ALWAYS STEADY
    rom[100] = 29'h000000c;   // CONSTANT: NOP
    rom[101] = 29'h2230023;   // LOAD V1
    rom[102] = 29'h870c000;   // SUB s.SPEED
    rom[103] = 29'h08000e3;   // HALF 3
    rom[104] = 29'h050c000;   // ADD s.SPEED
    rom[105] = 29'h1400000;   // OUT SPEED_A0
    rom[106] = 29'h0000000;   // STEADY: NOP
    rom[107] = 29'h2200000;   // LOAD C_ZERO
    rom[108] = 29'h1238000;   // STORE UPS
    rom[109] = 29'h123c000;   // STORE DOWNS
    rom[110] = 29'h1a03080;   // JMP ALWAYS NEXT
    rom[111] = 29'h0000011;   // FIT: NOP
    rom[112] = 29'h2244012;   // LOAD P1
    rom[113] = 29'h0448000;   // ADD P2
    rom[114] = 29'h125000c;   // STORE T1
    rom[115] = 29'h223000d;   // LOAD V1
    rom[116] = 29'h8634000;   // SUB V2
    rom[117] = 29'h1a0a280;   // JMP NEG SLOWER
    rom[118] = 29'h2200000;   // LOAD C_ZERO
    rom[119] = 29'h123c00e;   // STORE DOWNS
    rom[120] = 29'h2238008;   // LOAD UPS
    rom[121] = 29'h8620000;   // SUB C_ONE
    rom[122] = 29'h1a0a188;   // JMP NEG FIRST_UP
    rom[123] = 29'h8620000;   // SUB C_ONE
    rom[124] = 29'h1240009;   // STORE HOLD
    rom[125] = 29'h2224000;   // LOAD C_TWO
    rom[126] = 29'h123800c;   // STORE UPS
    rom[127] = 29'h223000d;   // LOAD V1
    rom[128] = 29'h8634000;   // SUB V2
    rom[129] = 29'h0a00014;   // NUM
    rom[130] = 29'h18c50840;   // DIV T1 33
    rom[131] = 29'h1000000;   // QUOT
    rom[132] = 29'h124c000;   // STORE T0
    rom[133] = 29'h1a02740;   // JMP ALWAYS EXTRAPOLATE
    rom[134] = 29'h0000008;   // FIRST_UP: NOP
    rom[135] = 29'h2220000;   // LOAD C_ONE
    rom[136] = 29'h1238000;   // STORE UPS
    rom[137] = 29'h1a02fc0;   // JMP ALWAYS JUMPED
    rom[138] = 29'h0000000;   // SLOWER: NOP
    rom[139] = 29'h2200000;   // LOAD C_ZERO
    rom[140] = 29'h123800f;   // STORE UPS
    rom[141] = 29'h223c008;   // LOAD DOWNS
    rom[142] = 29'h8620000;   // SUB C_ONE
    rom[143] = 29'h1a0af08;   // JMP NEG FIRST_DOWN
    rom[144] = 29'h8620000;   // SUB C_ONE
    rom[145] = 29'h1240009;   // STORE HOLD
    rom[146] = 29'h2224000;   // LOAD C_TWO
    rom[147] = 29'h123c00d;   // STORE DOWNS
    rom[148] = 29'h223400c;   // LOAD V2
    rom[149] = 29'h8630000;   // SUB V1
    rom[150] = 29'h0a00014;   // NUM
    rom[151] = 29'h18c50840;   // DIV T1 33
    rom[152] = 29'h1000000;   // QUOT
    rom[153] = 29'h124c000;   // STORE T0
    rom[154] = 29'h2200013;   // LOAD C_ZERO
    rom[155] = 29'h864c000;   // SUB T0
    rom[156] = 29'h124c000;   // STORE T0
    rom[157] = 29'h1250011;   // EXTRAPOLATE: STORE T1
    rom[158] = 29'h2244000;   // LOAD P1
    rom[159] = 29'h0800046;   // HALF 1
    rom[160] = 29'h0418000;   // ADD C_LATENCY
    rom[161] = 29'h0a00014;   // NUM
    rom[162] = 29'h14e5080c;   // MUL T1 32
    rom[163] = 29'h0430000;   // ADD V1
    rom[164] = 29'h1250010;   // STORE T1
    rom[165] = 29'h2240000;   // LOAD HOLD
    rom[166] = 29'h1a0aa53;   // JMP NEG NO_ACCEL
    rom[167] = 29'h224c000;   // LOAD T0
    rom[168] = 29'h1a02ac0;   // JMP ALWAYS WAIT
    rom[169] = 29'h0000000;   // NO_ACCEL: NOP
    rom[170] = 29'h2200000;   // LOAD C_ZERO
    rom[171] = 29'h124c014;   // WAIT: STORE T0
    rom[172] = 29'h2250000;   // LOAD T1
    rom[173] = 29'h1a0acc0;   // JMP NEG ZERO
    rom[174] = 29'h1c03f40;   // WAIT 253
    rom[175] = 29'h1404013;   // OUT SPEED
    rom[176] = 29'h224c000;   // LOAD T0
    rom[177] = 29'h1408000;   // OUT ACCEL
    rom[178] = 29'h1a03080;   // JMP ALWAYS NEXT
    rom[179] = 29'h0000000;   // ZERO: NOP
    rom[180] = 29'h2200000;   // LOAD C_ZERO
    rom[181] = 29'h1400000;   // OUT SPEED_A0
    rom[182] = 29'h1a03080;   // JMP ALWAYS NEXT
    rom[183] = 29'h0000000;   // FIRST: NOP
    rom[184] = 29'h2200000;   // LOAD C_ZERO
    rom[185] = 29'h1238000;   // STORE UPS
    rom[186] = 29'h123c000;   // STORE DOWNS
    rom[187] = 29'h1604040;   // FLAG HAVE 1
    rom[188] = 29'h0000008;   // FIRST_DOWN: NOP
    rom[189] = 29'h2220000;   // LOAD C_ONE
    rom[190] = 29'h123c000;   // STORE DOWNS
    rom[191] = 29'h000000c;   // JUMPED: NOP
    rom[192] = 29'h2230000;   // LOAD V1
    rom[193] = 29'h1400000;   // OUT SPEED_A0
    rom[194] = 29'h000000c;   // NEXT: NOP
    rom[195] = 29'h2230000;   // LOAD V1
    rom[196] = 29'h1234011;   // STORE V2
    rom[197] = 29'h2244000;   // LOAD P1
    rom[198] = 29'h1248000;   // STORE P2
    rom[199] = 29'h1a033c0;   // JMP ALWAYS DONE
    rom[200] = 29'h0000021;   // ANCHOR: NOP
    rom[201] = 29'h2304000;   // LOAD s.STIME
    rom[202] = 29'h1228022;   // STORE W_TIME
    rom[203] = 29'h2308000;   // LOAD s.SPOSC
    rom[204] = 29'h122c000;   // STORE W_POSC
    rom[205] = 29'h1600040;   // FLAG ANCH 1
    rom[206] = 29'h1604000;   // FLAG HAVE 0
    rom[207] = 29'h1800000;   // DONE: DONE
    rom[208] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[209] = 29'h1600000;   // RESTART: FLAG ANCH 0
    rom[210] = 29'h1604000;   // FLAG HAVE 0
    rom[211] = 29'h1608000;   // FLAG BND 0
    rom[212] = 29'h1a00000;   // JMP ALWAYS IDLE
  end

  always @(posedge clk) begin
    word <= rom[pc];
  end

endmodule

`resetall
