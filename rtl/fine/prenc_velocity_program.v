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

  assign restart = 8'd251;

  integer i;
  initial begin
    for (i = 0; i < 256; i = i + 1) rom[i] = 29'd0;
    rom[0] = 29'h1a04940;   // IDLE: JMP PEND STEP
    rom[1] = 29'h1a10240;   // JMP HAVE AGE
    rom[2] = 29'h1a1c020;   // JMP NOT_ANCH IDLE
    rom[3] = 29'h230000d;   // LOAD s.NOW
    rom[4] = 29'h8634007;   // SUB W_TIME
    rom[5] = 29'h861c000;   // SUB C_OLD
    rom[6] = 29'h1a08000;   // JMP NEG IDLE
    rom[7] = 29'h1600000;   // FLAG ANCH 0
    rom[8] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[9] = 29'h0000020;   // AGE: NOP
    rom[10] = 29'h2300024;   // LOAD s.NOW
    rom[11] = 29'h8710000;   // SUB s.LTIME
    rom[12] = 29'h125c000;   // STORE T1
    rom[13] = 29'h1a24419;   // JMP NOT_BND BOUND
    rom[14] = 29'h8664000;   // SUB STOP_AT
    rom[15] = 29'h1a0c840;   // JMP NOT_NEG STOP
    rom[16] = 29'h0000025;   // BOUND: NOP
    rom[17] = 29'h2314004;   // LOAD s.LWIDTH
    rom[18] = 29'h0410000;   // ADD C_LEVEL0
    rom[19] = 29'h0a00017;   // NUM
    rom[20] = 29'h18cdcd00;   // DIV T1 52 abortable
    rom[21] = 29'h1000023;   // QUOT
    rom[22] = 29'h870c000;   // SUB s.SPEED
    rom[23] = 29'h1a0c023;   // JMP NOT_NEG IDLE
    rom[24] = 29'h050c000;   // ADD s.SPEED
    rom[25] = 29'h1400000;   // OUT SPEED_A0
    rom[26] = 29'h1a20000;   // JMP BND IDLE
    rom[27] = 29'h1608057;   // FLAG BND 1
    rom[28] = 29'h225c000;   // LOAD T1
    rom[29] = 29'h0800057;   // HALF 1
    rom[30] = 29'h045c000;   // ADD T1
    rom[31] = 29'h1264000;   // STORE STOP_AT
    rom[32] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[33] = 29'h0000000;   // STOP: NOP
    rom[34] = 29'h2200000;   // LOAD C_ZERO
    rom[35] = 29'h1400000;   // OUT SPEED_A0
    rom[36] = 29'h1a03ec0;   // JMP ALWAYS RESTART
    rom[37] = 29'h1608000;   // STEP: FLAG BND 0
    rom[38] = 29'h1a1fca1;   // JMP NOT_ANCH ANCHOR
    rom[39] = 29'h230400d;   // LOAD s.STIME
    rom[40] = 29'h8634000;   // SUB W_TIME
    rom[41] = 29'h1250002;   // STORE P1
    rom[42] = 29'h8608000;   // SUB C_SHORT
    rom[43] = 29'h1a0be62;   // JMP NEG DONE
    rom[44] = 29'h230800e;   // LOAD s.SPOSC
    rom[45] = 29'h8638000;   // SUB W_POSC
    rom[46] = 29'h125c000;   // STORE T1
    rom[47] = 29'h1a0bc8a;   // JMP NEG ANCHOR
    rom[48] = 29'h8628000;   // SUB C_CYCLE
    rom[49] = 29'h1a0be43;   // JMP NEG DONE
    rom[50] = 29'h860c000;   // SUB C_QUARTERS
    rom[51] = 29'h1a09114;   // JMP NEG CLOSE
    rom[52] = 29'h2250001;   // LOAD P1
    rom[53] = 29'h8604000;   // SUB C_WINDOW
    rom[54] = 29'h1a0be40;   // JMP NEG DONE
    rom[55] = 29'h220000a;   // LOAD C_ZERO
    rom[56] = 29'h8628000;   // SUB C_CYCLE
    rom[57] = 29'h1a0d117;   // JMP NOT_NEG CLOSE
    rom[58] = 29'h225c000;   // LOAD T1
    rom[59] = 29'h0800300;   // HALF 12
    rom[60] = 29'h1258000;   // STORE T0
    rom[61] = 29'h0800080;   // HALF 2
    rom[62] = 29'h1260016;   // STORE T2
    rom[63] = 29'h8658018;   // SUB T0
    rom[64] = 29'h0460018;   // ADD T2
    rom[65] = 29'h0460018;   // ADD T2
    rom[66] = 29'h0460000;   // ADD T2
    rom[67] = 29'h1a0be40;   // JMP NEG DONE
    rom[68] = 29'h0000021;   // CLOSE: NOP
    rom[69] = 29'h2304000;   // LOAD s.STIME
    rom[70] = 29'h1234022;   // STORE W_TIME
    rom[71] = 29'h2308000;   // LOAD s.SPOSC
    rom[72] = 29'h1238017;   // STORE W_POSC
    rom[73] = 29'h225c000;   // LOAD T1
    rom[74] = 29'h0a00014;   // NUM
    rom[75] = 29'h18c50d00;   // DIV P1 52
    rom[76] = 29'h1000000;   // QUOT
    rom[77] = 29'h123c000;   // STORE V1
    rom[78] = 29'h1a177e3;   // JMP NOT_HAVE FIRST
    rom[79] = 29'h230c005;   // LOAD s.SPEED
    rom[80] = 29'h0414000;   // ADD C_2DELTA
    rom[81] = 29'h0a00014;   // NUM
    rom[82] = 29'h18c50800;   // DIV P1 32
    rom[83] = 29'h1000000;   // QUOT
    rom[84] = 29'h125800f;   // STORE T0
    rom[85] = 29'h223c023;   // LOAD V1
    rom[86] = 29'h870c000;   // SUB s.SPEED
    rom[87] = 29'h0800040;   // HALF 1
    rom[88] = 29'h125c000;   // STORE T1
    rom[89] = 29'h1a098d6;   // JMP NEG BELOW
    rom[90] = 29'h8658000;   // SUB T0
    rom[91] = 29'h1a0e10c;   // JMP NOT_NEG AGREE
    rom[92] = 29'h2230000;   // LOAD C_TREND
    rom[93] = 29'h127001b;   // STORE DOWN_LEFT
    rom[94] = 29'h226c008;   // LOAD UP_LEFT
    rom[95] = 29'h8620000;   // SUB C_ONE
    rom[96] = 29'h1a09d40;   // JMP NEG TREND
    rom[97] = 29'h126c000;   // STORE UP_LEFT
    rom[98] = 29'h1a01b00;   // JMP ALWAYS COUNT
    rom[99] = 29'h0000016;   // BELOW: NOP
    rom[100] = 29'h0458000;   // ADD T0
    rom[101] = 29'h1a0a10c;   // JMP NEG AGREE
    rom[102] = 29'h2230000;   // LOAD C_TREND
    rom[103] = 29'h126c01c;   // STORE UP_LEFT
    rom[104] = 29'h2270008;   // LOAD DOWN_LEFT
    rom[105] = 29'h8620000;   // SUB C_ONE
    rom[106] = 29'h1a09d40;   // JMP NEG TREND
    rom[107] = 29'h1270000;   // STORE DOWN_LEFT
    rom[108] = 29'h000001a;   // COUNT: NOP
    rom[109] = 29'h2268008;   // LOAD RUNS
    rom[110] = 29'h8620000;   // SUB C_ONE
    rom[111] = 29'h1a09e00;   // JMP NEG SETTLED
    rom[112] = 29'h1268017;   // COUNTED: STORE RUNS
    rom[113] = 29'h225c000;   // LOAD T1
    rom[114] = 29'h1a2dec0;   // JMP NOT_STALE FRESH
    rom[115] = 29'h0800080;   // HALF 2
    rom[116] = 29'h1a01f00;   // JMP ALWAYS MEAN
    rom[117] = 29'h000000b;   // TREND: NOP
    rom[118] = 29'h222c000;   // LOAD C_SETTLED
    rom[119] = 29'h1a01c00;   // JMP ALWAYS COUNTED
    rom[120] = 29'h0000017;   // SETTLED: NOP
    rom[121] = 29'h225c000;   // LOAD T1
    rom[122] = 29'h0800100;   // HALF 4
    rom[123] = 29'h160c040;   // FRESH: FLAG STALE 1
    rom[124] = 29'h0000023;   // MEAN: NOP
    rom[125] = 29'h050c000;   // ADD s.SPEED
    rom[126] = 29'h1400000;   // OUT SPEED_A0
    rom[127] = 29'h0000000;   // STEADY: NOP
    rom[128] = 29'h2200000;   // LOAD C_ZERO
    rom[129] = 29'h1244000;   // STORE UPS
    rom[130] = 29'h1248000;   // STORE DOWNS
    rom[131] = 29'h1a03b00;   // JMP ALWAYS NEXT
    rom[132] = 29'h160c00b;   // AGREE: FLAG STALE 0
    rom[133] = 29'h222c000;   // LOAD C_SETTLED
    rom[134] = 29'h126800f;   // STORE RUNS
    rom[135] = 29'h223c010;   // LOAD V1
    rom[136] = 29'h8640000;   // SUB V2
    rom[137] = 29'h0800040;   // HALF 1
    rom[138] = 29'h1a0a396;   // JMP NEG BELOW_V2
    rom[139] = 29'h8658000;   // SUB T0
    rom[140] = 29'h1a0e5c0;   // JMP NOT_NEG FIT
    rom[141] = 29'h1a02440;   // JMP ALWAYS AGREED
    rom[142] = 29'h0000016;   // BELOW_V2: NOP
    rom[143] = 29'h0458000;   // ADD T0
    rom[144] = 29'h1a0a5c0;   // JMP NEG FIT
    rom[145] = 29'h000000f;   // AGREED: NOP
    rom[146] = 29'h223c010;   // LOAD V1
    rom[147] = 29'h0440000;   // ADD V2
    rom[148] = 29'h0800040;   // HALF 1
    rom[149] = 29'h1400000;   // OUT SPEED_A0
    rom[150] = 29'h1a01fc0;   // JMP ALWAYS STEADY
    rom[151] = 29'h0000014;   // FIT: NOP
    rom[152] = 29'h2250015;   // LOAD P1
    rom[153] = 29'h0454000;   // ADD P2
    rom[154] = 29'h125c00f;   // STORE T1
    rom[155] = 29'h223c010;   // LOAD V1
    rom[156] = 29'h8640000;   // SUB V2
    rom[157] = 29'h1a0ac80;   // JMP NEG SLOWER
    rom[158] = 29'h2200000;   // LOAD C_ZERO
    rom[159] = 29'h1248011;   // STORE DOWNS
    rom[160] = 29'h2244008;   // LOAD UPS
    rom[161] = 29'h8620000;   // SUB C_ONE
    rom[162] = 29'h1a0ab88;   // JMP NEG FIRST_UP
    rom[163] = 29'h8620000;   // SUB C_ONE
    rom[164] = 29'h124c009;   // STORE HOLD
    rom[165] = 29'h2224000;   // LOAD C_TWO
    rom[166] = 29'h124400f;   // STORE UPS
    rom[167] = 29'h223c010;   // LOAD V1
    rom[168] = 29'h8640000;   // SUB V2
    rom[169] = 29'h0a00017;   // NUM
    rom[170] = 29'h18c5c840;   // DIV T1 33
    rom[171] = 29'h1000000;   // QUOT
    rom[172] = 29'h1258000;   // STORE T0
    rom[173] = 29'h1a03140;   // JMP ALWAYS EXTRAPOLATE
    rom[174] = 29'h0000008;   // FIRST_UP: NOP
    rom[175] = 29'h2220000;   // LOAD C_ONE
    rom[176] = 29'h1244000;   // STORE UPS
    rom[177] = 29'h1a03a40;   // JMP ALWAYS JUMPED
    rom[178] = 29'h0000000;   // SLOWER: NOP
    rom[179] = 29'h2200000;   // LOAD C_ZERO
    rom[180] = 29'h1244012;   // STORE UPS
    rom[181] = 29'h2248008;   // LOAD DOWNS
    rom[182] = 29'h8620000;   // SUB C_ONE
    rom[183] = 29'h1a0b988;   // JMP NEG FIRST_DOWN
    rom[184] = 29'h8620000;   // SUB C_ONE
    rom[185] = 29'h124c009;   // STORE HOLD
    rom[186] = 29'h2224000;   // LOAD C_TWO
    rom[187] = 29'h1248010;   // STORE DOWNS
    rom[188] = 29'h224000f;   // LOAD V2
    rom[189] = 29'h863c000;   // SUB V1
    rom[190] = 29'h0a00017;   // NUM
    rom[191] = 29'h18c5c840;   // DIV T1 33
    rom[192] = 29'h1000000;   // QUOT
    rom[193] = 29'h1258000;   // STORE T0
    rom[194] = 29'h2200016;   // LOAD C_ZERO
    rom[195] = 29'h8658000;   // SUB T0
    rom[196] = 29'h1258000;   // STORE T0
    rom[197] = 29'h125c014;   // EXTRAPOLATE: STORE T1
    rom[198] = 29'h2250000;   // LOAD P1
    rom[199] = 29'h0800046;   // HALF 1
    rom[200] = 29'h0418000;   // ADD C_LATENCY
    rom[201] = 29'h0a00017;   // NUM
    rom[202] = 29'h14e5c80f;   // MUL T1 32
    rom[203] = 29'h043c000;   // ADD V1
    rom[204] = 29'h125c013;   // STORE T1
    rom[205] = 29'h224c000;   // LOAD HOLD
    rom[206] = 29'h1a0b456;   // JMP NEG NO_ACCEL
    rom[207] = 29'h2258000;   // LOAD T0
    rom[208] = 29'h1a034c0;   // JMP ALWAYS WAIT
    rom[209] = 29'h0000000;   // NO_ACCEL: NOP
    rom[210] = 29'h2200000;   // LOAD C_ZERO
    rom[211] = 29'h1258017;   // WAIT: STORE T0
    rom[212] = 29'h225c000;   // LOAD T1
    rom[213] = 29'h1a0b6c0;   // JMP NEG ZERO
    rom[214] = 29'h1c03f40;   // WAIT 253
    rom[215] = 29'h1404016;   // OUT SPEED
    rom[216] = 29'h2258000;   // LOAD T0
    rom[217] = 29'h1408000;   // OUT ACCEL
    rom[218] = 29'h1a03b00;   // JMP ALWAYS NEXT
    rom[219] = 29'h0000000;   // ZERO: NOP
    rom[220] = 29'h2200000;   // LOAD C_ZERO
    rom[221] = 29'h1400000;   // OUT SPEED_A0
    rom[222] = 29'h1a03b00;   // JMP ALWAYS NEXT
    rom[223] = 29'h000000b;   // FIRST: NOP
    rom[224] = 29'h222c000;   // LOAD C_SETTLED
    rom[225] = 29'h1268000;   // STORE RUNS
    rom[226] = 29'h2200000;   // LOAD C_ZERO
    rom[227] = 29'h1244000;   // STORE UPS
    rom[228] = 29'h1248000;   // STORE DOWNS
    rom[229] = 29'h1604040;   // FLAG HAVE 1
    rom[230] = 29'h0000008;   // FIRST_DOWN: NOP
    rom[231] = 29'h2220000;   // LOAD C_ONE
    rom[232] = 29'h1248000;   // STORE DOWNS
    rom[233] = 29'h000000f;   // JUMPED: NOP
    rom[234] = 29'h223c000;   // LOAD V1
    rom[235] = 29'h1400000;   // OUT SPEED_A0
    rom[236] = 29'h000000f;   // NEXT: NOP
    rom[237] = 29'h223c000;   // LOAD V1
    rom[238] = 29'h1240014;   // STORE V2
    rom[239] = 29'h2250000;   // LOAD P1
    rom[240] = 29'h1254000;   // STORE P2
    rom[241] = 29'h1a03e40;   // JMP ALWAYS DONE
    rom[242] = 29'h0000021;   // ANCHOR: NOP
    rom[243] = 29'h2304000;   // LOAD s.STIME
    rom[244] = 29'h1234022;   // STORE W_TIME
    rom[245] = 29'h2308000;   // LOAD s.SPOSC
    rom[246] = 29'h1238000;   // STORE W_POSC
    rom[247] = 29'h1600040;   // FLAG ANCH 1
    rom[248] = 29'h1604000;   // FLAG HAVE 0
    rom[249] = 29'h1800000;   // DONE: DONE
    rom[250] = 29'h1a00000;   // JMP ALWAYS IDLE
    rom[251] = 29'h1600000;   // RESTART: FLAG ANCH 0
    rom[252] = 29'h1604000;   // FLAG HAVE 0
    rom[253] = 29'h1608000;   // FLAG BND 0
    rom[254] = 29'h1a00000;   // JMP ALWAYS IDLE
  end

  always @(posedge clk) begin
    word <= rom[pc];
  end

endmodule

`resetall
