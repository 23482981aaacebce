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

  assign restart = 8'd224;

  integer i;
  initial begin
    for (i = 0; i < 256; i = i + 1) rom[i] = 29'd0;
    rom[0] = 29'h1a04a00;   // IDLE: JMP PEND STEP
    rom[1] = 29'h1a10240;   // JMP HAVE AGE
    rom[2] = 29'h1a1c020;   // JMP NOT_ANCH IDLE
    rom[3] = 29'h230000b;   // LOAD s.NOW
    rom[4] = 29'h862c007;   // SUB W_TIME
    rom[5] = 29'h861c000;   // SUB C_OLD
    rom[6] = 29'h1a08000;   // JMP NEG IDLE
    rom[7] = 29'h1600000;   // FLAG ANCH 0
    rom[8] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[9] = 29'h0000020;   // AGE: NOP
    rom[10] = 29'h2300024;   // LOAD s.NOW
    rom[11] = 29'h8710000;   // SUB s.LTIME
    rom[12] = 29'h1254000;   // STORE T1
    rom[13] = 29'h1a24417;   // JMP NOT_BND BOUND
    rom[14] = 29'h865c000;   // SUB STOP_AT
    rom[15] = 29'h1a0c840;   // JMP NOT_NEG STOP
    rom[16] = 29'h0000025;   // BOUND: NOP
    rom[17] = 29'h2314004;   // LOAD s.LWIDTH
    rom[18] = 29'h0410000;   // ADD C_LEVEL0
    rom[19] = 29'h0a00015;   // NUM
    rom[20] = 29'h18cd4d00;   // DIV T1 52 abortable
    rom[21] = 29'h1000023;   // QUOT
    rom[22] = 29'h870c000;   // SUB s.SPEED
    rom[23] = 29'h1a0c023;   // JMP NOT_NEG IDLE
    rom[24] = 29'h050c000;   // ADD s.SPEED
    rom[25] = 29'h1400000;   // OUT SPEED_A0
    rom[26] = 29'h1a20000;   // JMP BND IDLE
    rom[27] = 29'h1608055;   // FLAG BND 1
    rom[28] = 29'h2254000;   // LOAD T1
    rom[29] = 29'h0800055;   // HALF 1
    rom[30] = 29'h0454000;   // ADD T1
    rom[31] = 29'h125c000;   // STORE STOP_AT
    rom[32] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[33] = 29'h0000000;   // STOP: NOP
    rom[34] = 29'h2200000;   // LOAD C_ZERO
    rom[35] = 29'h1400000;   // OUT SPEED_A0
    rom[36] = 29'h1600000;   // FLAG ANCH 0
    rom[37] = 29'h1604000;   // FLAG HAVE 0
    rom[38] = 29'h1608000;   // FLAG BND 0
    rom[39] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[40] = 29'h1608000;   // STEP: FLAG BND 0
    rom[41] = 29'h1a1f5e1;   // JMP NOT_ANCH ANCHOR
    rom[42] = 29'h230400b;   // LOAD s.STIME
    rom[43] = 29'h862c000;   // SUB W_TIME
    rom[44] = 29'h1248002;   // STORE P1
    rom[45] = 29'h8608000;   // SUB C_SHORT
    rom[46] = 29'h1a0b7a2;   // JMP NEG DONE
    rom[47] = 29'h230800c;   // LOAD s.SPOSC
    rom[48] = 29'h8630000;   // SUB W_POSC
    rom[49] = 29'h1254000;   // STORE T1
    rom[50] = 29'h1a0b5ca;   // JMP NEG ANCHOR
    rom[51] = 29'h8628000;   // SUB C_CYCLE
    rom[52] = 29'h1a0b783;   // JMP NEG DONE
    rom[53] = 29'h860c000;   // SUB C_QUARTERS
    rom[54] = 29'h1a091d2;   // JMP NEG CLOSE
    rom[55] = 29'h2248001;   // LOAD P1
    rom[56] = 29'h8604000;   // SUB C_WINDOW
    rom[57] = 29'h1a0b780;   // JMP NEG DONE
    rom[58] = 29'h220000a;   // LOAD C_ZERO
    rom[59] = 29'h8628000;   // SUB C_CYCLE
    rom[60] = 29'h1a0d1d5;   // JMP NOT_NEG CLOSE
    rom[61] = 29'h2254000;   // LOAD T1
    rom[62] = 29'h0800300;   // HALF 12
    rom[63] = 29'h1250000;   // STORE T0
    rom[64] = 29'h0800080;   // HALF 2
    rom[65] = 29'h1258014;   // STORE T2
    rom[66] = 29'h8650016;   // SUB T0
    rom[67] = 29'h0458016;   // ADD T2
    rom[68] = 29'h0458016;   // ADD T2
    rom[69] = 29'h0458000;   // ADD T2
    rom[70] = 29'h1a0b780;   // JMP NEG DONE
    rom[71] = 29'h0000021;   // CLOSE: NOP
    rom[72] = 29'h2304000;   // LOAD s.STIME
    rom[73] = 29'h122c022;   // STORE W_TIME
    rom[74] = 29'h2308000;   // LOAD s.SPOSC
    rom[75] = 29'h1230015;   // STORE W_POSC
    rom[76] = 29'h2254000;   // LOAD T1
    rom[77] = 29'h0a00012;   // NUM
    rom[78] = 29'h18c48d00;   // DIV P1 52
    rom[79] = 29'h1000000;   // QUOT
    rom[80] = 29'h1234000;   // STORE V1
    rom[81] = 29'h1a171a3;   // JMP NOT_HAVE FIRST
    rom[82] = 29'h230c005;   // LOAD s.SPEED
    rom[83] = 29'h0414000;   // ADD C_2DELTA
    rom[84] = 29'h0a00012;   // NUM
    rom[85] = 29'h18c48800;   // DIV P1 32
    rom[86] = 29'h1000000;   // QUOT
    rom[87] = 29'h125000d;   // STORE T0
    rom[88] = 29'h2234023;   // LOAD V1
    rom[89] = 29'h870c000;   // SUB s.SPEED
    rom[90] = 29'h0800040;   // HALF 1
    rom[91] = 29'h1a097d4;   // JMP NEG BELOW
    rom[92] = 29'h8650000;   // SUB T0
    rom[93] = 29'h1a09cc0;   // JMP NEG CONSTANT
    rom[94] = 29'h1a01880;   // JMP ALWAYS AGREE
    rom[95] = 29'h0000014;   // BELOW: NOP
    rom[96] = 29'h0450000;   // ADD T0
    rom[97] = 29'h1a0dcc0;   // JMP NOT_NEG CONSTANT
    rom[98] = 29'h000000d;   // AGREE: NOP
    rom[99] = 29'h223400e;   // LOAD V1
    rom[100] = 29'h8638000;   // SUB V2
    rom[101] = 29'h0800040;   // HALF 1
    rom[102] = 29'h1a09a94;   // JMP NEG BELOW_V2
    rom[103] = 29'h8650000;   // SUB T0
    rom[104] = 29'h1a0df80;   // JMP NOT_NEG FIT
    rom[105] = 29'h1a01b40;   // JMP ALWAYS AGREED
    rom[106] = 29'h0000014;   // BELOW_V2: NOP
    rom[107] = 29'h0450000;   // ADD T0
    rom[108] = 29'h1a09f80;   // JMP NEG FIT
    rom[109] = 29'h000000d;   // AGREED: NOP
    rom[110] = 29'h223400e;   // LOAD V1
    rom[111] = 29'h0438000;   // ADD V2
    rom[112] = 29'h0800040;   // HALF 1
    rom[113] = 29'h1400000;   // OUT SPEED_A0
    rom[114] = 29'h1a01e40;   // JMP ALWAYS STEADY
    rom[115] = 29'h000000d;   // CONSTANT: NOP
    rom[116] = 29'h2234023;   // LOAD V1
    rom[117] = 29'h870c000;   // SUB s.SPEED
    rom[118] = 29'h08000e3;   // HALF 3
    rom[119] = 29'h050c000;   // ADD s.SPEED
    rom[120] = 29'h1400000;   // OUT SPEED_A0
    rom[121] = 29'h0000000;   // STEADY: NOP
    rom[122] = 29'h2200000;   // LOAD C_ZERO
    rom[123] = 29'h123c000;   // STORE UPS
    rom[124] = 29'h1240000;   // STORE DOWNS
    rom[125] = 29'h1a03440;   // JMP ALWAYS NEXT
    rom[126] = 29'h0000012;   // FIT: NOP
    rom[127] = 29'h2248013;   // LOAD P1
    rom[128] = 29'h044c000;   // ADD P2
    rom[129] = 29'h125400d;   // STORE T1
    rom[130] = 29'h223400e;   // LOAD V1
    rom[131] = 29'h8638000;   // SUB V2
    rom[132] = 29'h1a0a640;   // JMP NEG SLOWER
    rom[133] = 29'h2200000;   // LOAD C_ZERO
    rom[134] = 29'h124000f;   // STORE DOWNS
    rom[135] = 29'h223c008;   // LOAD UPS
    rom[136] = 29'h8620000;   // SUB C_ONE
    rom[137] = 29'h1a0a548;   // JMP NEG FIRST_UP
    rom[138] = 29'h8620000;   // SUB C_ONE
    rom[139] = 29'h1244009;   // STORE HOLD
    rom[140] = 29'h2224000;   // LOAD C_TWO
    rom[141] = 29'h123c00d;   // STORE UPS
    rom[142] = 29'h223400e;   // LOAD V1
    rom[143] = 29'h8638000;   // SUB V2
    rom[144] = 29'h0a00015;   // NUM
    rom[145] = 29'h18c54840;   // DIV T1 33
    rom[146] = 29'h1000000;   // QUOT
    rom[147] = 29'h1250000;   // STORE T0
    rom[148] = 29'h1a02b00;   // JMP ALWAYS EXTRAPOLATE
    rom[149] = 29'h0000008;   // FIRST_UP: NOP
    rom[150] = 29'h2220000;   // LOAD C_ONE
    rom[151] = 29'h123c000;   // STORE UPS
    rom[152] = 29'h1a03380;   // JMP ALWAYS JUMPED
    rom[153] = 29'h0000000;   // SLOWER: NOP
    rom[154] = 29'h2200000;   // LOAD C_ZERO
    rom[155] = 29'h123c010;   // STORE UPS
    rom[156] = 29'h2240008;   // LOAD DOWNS
    rom[157] = 29'h8620000;   // SUB C_ONE
    rom[158] = 29'h1a0b2c8;   // JMP NEG FIRST_DOWN
    rom[159] = 29'h8620000;   // SUB C_ONE
    rom[160] = 29'h1244009;   // STORE HOLD
    rom[161] = 29'h2224000;   // LOAD C_TWO
    rom[162] = 29'h124000e;   // STORE DOWNS
    rom[163] = 29'h223800d;   // LOAD V2
    rom[164] = 29'h8634000;   // SUB V1
    rom[165] = 29'h0a00015;   // NUM
    rom[166] = 29'h18c54840;   // DIV T1 33
    rom[167] = 29'h1000000;   // QUOT
    rom[168] = 29'h1250000;   // STORE T0
    rom[169] = 29'h2200014;   // LOAD C_ZERO
    rom[170] = 29'h8650000;   // SUB T0
    rom[171] = 29'h1250000;   // STORE T0
    rom[172] = 29'h1254012;   // EXTRAPOLATE: STORE T1
    rom[173] = 29'h2248000;   // LOAD P1
    rom[174] = 29'h0800046;   // HALF 1
    rom[175] = 29'h0418000;   // ADD C_LATENCY
    rom[176] = 29'h0a00015;   // NUM
    rom[177] = 29'h14e5480d;   // MUL T1 32
    rom[178] = 29'h0434000;   // ADD V1
    rom[179] = 29'h1254011;   // STORE T1
    rom[180] = 29'h2244000;   // LOAD HOLD
    rom[181] = 29'h1a0ae14;   // JMP NEG NO_ACCEL
    rom[182] = 29'h2250000;   // LOAD T0
    rom[183] = 29'h1a02e80;   // JMP ALWAYS WAIT
    rom[184] = 29'h0000000;   // NO_ACCEL: NOP
    rom[185] = 29'h2200000;   // LOAD C_ZERO
    rom[186] = 29'h1250015;   // WAIT: STORE T0
    rom[187] = 29'h2254000;   // LOAD T1
    rom[188] = 29'h1a0b080;   // JMP NEG ZERO
    rom[189] = 29'h1c03f40;   // WAIT 253
    rom[190] = 29'h1404014;   // OUT SPEED
    rom[191] = 29'h2250000;   // LOAD T0
    rom[192] = 29'h1408000;   // OUT ACCEL
    rom[193] = 29'h1a03440;   // JMP ALWAYS NEXT
    rom[194] = 29'h0000000;   // ZERO: NOP
    rom[195] = 29'h2200000;   // LOAD C_ZERO
    rom[196] = 29'h1400000;   // OUT SPEED_A0
    rom[197] = 29'h1a03440;   // JMP ALWAYS NEXT
    rom[198] = 29'h0000000;   // FIRST: NOP
    rom[199] = 29'h2200000;   // LOAD C_ZERO
    rom[200] = 29'h123c000;   // STORE UPS
    rom[201] = 29'h1240000;   // STORE DOWNS
    rom[202] = 29'h1604040;   // FLAG HAVE 1
    rom[203] = 29'h0000008;   // FIRST_DOWN: NOP
    rom[204] = 29'h2220000;   // LOAD C_ONE
    rom[205] = 29'h1240000;   // STORE DOWNS
    rom[206] = 29'h000000d;   // JUMPED: NOP
    rom[207] = 29'h2234000;   // LOAD V1
    rom[208] = 29'h1400000;   // OUT SPEED_A0
    rom[209] = 29'h000000d;   // NEXT: NOP
    rom[210] = 29'h2234000;   // LOAD V1
    rom[211] = 29'h1238012;   // STORE V2
    rom[212] = 29'h2248000;   // LOAD P1
    rom[213] = 29'h124c000;   // STORE P2
    rom[214] = 29'h1a03780;   // JMP ALWAYS DONE
    rom[215] = 29'h0000021;   // ANCHOR: NOP
    rom[216] = 29'h2304000;   // LOAD s.STIME
    rom[217] = 29'h122c022;   // STORE W_TIME
    rom[218] = 29'h2308000;   // LOAD s.SPOSC
    rom[219] = 29'h1230000;   // STORE W_POSC
    rom[220] = 29'h1600040;   // FLAG ANCH 1
    rom[221] = 29'h1604000;   // FLAG HAVE 0
    rom[222] = 29'h1800000;   // DONE: DONE
    rom[223] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[224] = 29'h1600000;   // RESTART: FLAG ANCH 0
    rom[225] = 29'h1604000;   // FLAG HAVE 0
    rom[226] = 29'h1608000;   // FLAG BND 0
    rom[227] = 29'h1a00000;   // JMP ALWAYS IDLE
  end

  always @(posedge clk) begin
    word <= rom[pc];
  end

endmodule

`resetall
