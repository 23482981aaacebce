// SPDX-License-Identifier: Apache-2.0
// prenc_velocity_program: prenc_velocity's program in block RAM, a word a clock:
// {step, invert, mul, load, quot, op[3:0], special, abortable, a[4:0], n[8:0], next_s,
// next_a[4:0]} (prenc.fine.engine, prenc.fine.program; docs/fine.md). step, invert,
// mul, load, quot: the adder's controls, decoded here (DIV or MUL; SUB, DIV or SIGN;
// MUL; LOAD; QUOT: the quotient through the adder, plus RF[0], which is 0).
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
  input  wire [8:0]  pc,
  output reg  [30:0] word,      // the word at pc, a clock later
  output wire [8:0]  restart    // where a restart goes
);

  reg [30:0] rom [0:511];

  assign restart = 9'd296;

  integer i;
  initial begin
    for (i = 0; i < 512; i = i + 1) rom[i] = 31'd0;
    rom[0] = 31'h03408e00;   // IDLE: JMP PEND STEP
    rom[1] = 31'h03470a40;   // JMP DUE UPDATE
    rom[2] = 31'h03420280;   // CHECKS: JMP HAVE AGE
    rom[3] = 31'h03438020;   // JMP NOT_ANCH IDLE
    rom[4] = 31'h0860000d;   // LOAD s.NOW
    rom[5] = 31'h20c68007;   // SUB W_TIME
    rom[6] = 31'h20c38000;   // SUB C_OLD
    rom[7] = 31'h03410000;   // JMP NEG IDLE
    rom[8] = 31'h02c00000;   // FLAG ANCH 0
    rom[9] = 31'h03400000;   // JMP ALWAYS IDLE
    rom[10] = 31'h00000020;   // AGE: NOP
    rom[11] = 31'h08600023;   // LOAD s.NOW
    rom[12] = 31'h20e18000;   // SUB s.LTIME
    rom[13] = 31'h024b0000;   // STORE T1
    rom[14] = 31'h03448458;   // JMP NOT_BND BOUND
    rom[15] = 31'h20cc0000;   // SUB STOP_AT
    rom[16] = 31'h03418940;   // JMP NOT_NEG STOP
    rom[17] = 31'h00000024;   // BOUND: NOP
    rom[18] = 31'h08620004;   // LOAD s.LWIDTH
    rom[19] = 31'h00820000;   // ADD C_LEVEL0
    rom[20] = 31'h01400016;   // NUM
    rom[21] = 31'h619b08c0;   // DIV T1 35 abortable
    rom[22] = 31'h0600001c;   // QUOT
    rom[23] = 31'h20ce0000;   // SUB S
    rom[24] = 31'h0341801c;   // JMP NOT_NEG IDLE
    rom[25] = 31'h008e0000;   // ADD S
    rom[26] = 31'h024e0000;   // STORE S
    rom[27] = 31'h02c20008;   // FLAG ACCEL 0
    rom[28] = 31'h23c40000;   // SIGN C_ONE
    rom[29] = 31'h02800000;   // OUT VELOCITY
    rom[30] = 31'h03440000;   // JMP BND IDLE
    rom[31] = 31'h02c10056;   // FLAG BND 1
    rom[32] = 31'h084b0000;   // LOAD T1
    rom[33] = 31'h01000056;   // HALF 1
    rom[34] = 31'h008b0000;   // ADD T1
    rom[35] = 31'h024c0000;   // STORE STOP_AT
    rom[36] = 31'h03400000;   // JMP ALWAYS IDLE
    rom[37] = 31'h00000000;   // STOP: NOP
    rom[38] = 31'h08400000;   // LOAD C_ZERO
    rom[39] = 31'h02800000;   // OUT VELOCITY
    rom[40] = 31'h03404a00;   // JMP ALWAYS RESTART
    rom[41] = 31'h0000001c;   // UPDATE: NOP
    rom[42] = 31'h084e001d;   // LOAD S
    rom[43] = 31'h008e8000;   // ADD A
    rom[44] = 31'h03410c80;   // JMP NEG HALT
    rom[45] = 31'h024e0008;   // STORE S
    rom[46] = 31'h23c40000;   // SIGN C_ONE
    rom[47] = 31'h02800000;   // OUT VELOCITY
    rom[48] = 31'h02c28000;   // FLAG TICK 0
    rom[49] = 31'h03400000;   // JMP ALWAYS IDLE
    rom[50] = 31'h00000000;   // HALT: NOP
    rom[51] = 31'h08400000;   // LOAD C_ZERO
    rom[52] = 31'h024e0000;   // STORE S
    rom[53] = 31'h02c20000;   // FLAG ACCEL 0
    rom[54] = 31'h02800000;   // OUT VELOCITY
    rom[55] = 31'h03400080;   // JMP ALWAYS CHECKS
    rom[56] = 31'h02c10000;   // STEP: FLAG BND 0
    rom[57] = 31'h0343c7e1;   // JMP NOT_ANCH ANCHOR
    rom[58] = 31'h0860800d;   // LOAD s.STIME
    rom[59] = 31'h20c68000;   // SUB W_TIME
    rom[60] = 31'h02498002;   // STORE P1
    rom[61] = 31'h20c10000;   // SUB C_SHORT
    rom[62] = 31'h034149a2;   // JMP NEG DONE
    rom[63] = 31'h0861000e;   // LOAD s.SPOSC
    rom[64] = 31'h20c70000;   // SUB W_POSC
    rom[65] = 31'h024b0000;   // STORE T1
    rom[66] = 31'h034147ca;   // JMP NEG ANCHOR
    rom[67] = 31'h20c50000;   // SUB C_CYCLE
    rom[68] = 31'h03414983;   // JMP NEG DONE
    rom[69] = 31'h20c18000;   // SUB C_QUARTERS
    rom[70] = 31'h034115d3;   // JMP NEG CLOSE
    rom[71] = 31'h08498001;   // LOAD P1
    rom[72] = 31'h20c08000;   // SUB C_WINDOW
    rom[73] = 31'h03414980;   // JMP NEG DONE
    rom[74] = 31'h0840000a;   // LOAD C_ZERO
    rom[75] = 31'h20c50000;   // SUB C_CYCLE
    rom[76] = 31'h034195d6;   // JMP NOT_NEG CLOSE
    rom[77] = 31'h084b0000;   // LOAD T1
    rom[78] = 31'h01000300;   // HALF 12
    rom[79] = 31'h024a8000;   // STORE T0
    rom[80] = 31'h01000080;   // HALF 2
    rom[81] = 31'h024b8015;   // STORE T2
    rom[82] = 31'h20ca8017;   // SUB T0
    rom[83] = 31'h008b8017;   // ADD T2
    rom[84] = 31'h008b8017;   // ADD T2
    rom[85] = 31'h008b8000;   // ADD T2
    rom[86] = 31'h03414980;   // JMP NEG DONE
    rom[87] = 31'h00000021;   // CLOSE: NOP
    rom[88] = 31'h08608000;   // LOAD s.STIME
    rom[89] = 31'h02468022;   // STORE W_TIME
    rom[90] = 31'h08610000;   // LOAD s.SPOSC
    rom[91] = 31'h02470016;   // STORE W_POSC
    rom[92] = 31'h084b0000;   // LOAD T1
    rom[93] = 31'h01400013;   // NUM
    rom[94] = 31'h61898d00;   // DIV P1 52
    rom[95] = 31'h06000000;   // QUOT
    rom[96] = 31'h02478000;   // STORE V1
    rom[97] = 31'h03479a5c;   // JMP NOT_DUE CLOSED
    rom[98] = 31'h084e001d;   // LOAD S
    rom[99] = 31'h008e8000;   // ADD A
    rom[100] = 31'h03411a40;   // JMP NEG CLOSED
    rom[101] = 31'h024e0008;   // STORE S
    rom[102] = 31'h23c40000;   // SIGN C_ONE
    rom[103] = 31'h02800000;   // OUT VELOCITY
    rom[104] = 31'h02c28000;   // FLAG TICK 0
    rom[105] = 31'h0342c25c;   // CLOSED: JMP NOT_HAVE FIRST
    rom[106] = 31'h084e0005;   // LOAD S
    rom[107] = 31'h00828000;   // ADD C_2DELTA
    rom[108] = 31'h01400013;   // NUM
    rom[109] = 31'h61898800;   // DIV P1 32
    rom[110] = 31'h06000000;   // QUOT
    rom[111] = 31'h024a800f;   // STORE T0
    rom[112] = 31'h0847801c;   // LOAD V1
    rom[113] = 31'h20ce0000;   // SUB S
    rom[114] = 31'h01000040;   // HALF 1
    rom[115] = 31'h024b0000;   // STORE T1
    rom[116] = 31'h03411f95;   // JMP NEG BELOW
    rom[117] = 31'h20ca8000;   // SUB T0
    rom[118] = 31'h0341a88c;   // JMP NOT_NEG AGREE
    rom[119] = 31'h08460000;   // LOAD C_TREND
    rom[120] = 31'h024d801a;   // STORE DOWN_LEFT
    rom[121] = 31'h084d0008;   // LOAD UP_LEFT
    rom[122] = 31'h20c40000;   // SUB C_ONE
    rom[123] = 31'h03412400;   // JMP NEG TREND
    rom[124] = 31'h024d0000;   // STORE UP_LEFT
    rom[125] = 31'h034021c0;   // JMP ALWAYS COUNT
    rom[126] = 31'h00000015;   // BELOW: NOP
    rom[127] = 31'h008a8000;   // ADD T0
    rom[128] = 31'h0341288c;   // JMP NEG AGREE
    rom[129] = 31'h08460000;   // LOAD C_TREND
    rom[130] = 31'h024d001b;   // STORE UP_LEFT
    rom[131] = 31'h084d8008;   // LOAD DOWN_LEFT
    rom[132] = 31'h20c40000;   // SUB C_ONE
    rom[133] = 31'h03412400;   // JMP NEG TREND
    rom[134] = 31'h024d8000;   // STORE DOWN_LEFT
    rom[135] = 31'h00000019;   // COUNT: NOP
    rom[136] = 31'h084c8008;   // LOAD RUNS
    rom[137] = 31'h20c40000;   // SUB C_ONE
    rom[138] = 31'h034124c0;   // JMP NEG SETTLED
    rom[139] = 31'h024c8016;   // COUNTED: STORE RUNS
    rom[140] = 31'h084b0000;   // LOAD T1
    rom[141] = 31'h0345a580;   // JMP NOT_STALE FRESH
    rom[142] = 31'h01000080;   // HALF 2
    rom[143] = 31'h034025c0;   // JMP ALWAYS MEAN
    rom[144] = 31'h0000000b;   // TREND: NOP
    rom[145] = 31'h08458000;   // LOAD C_SETTLED
    rom[146] = 31'h034022c0;   // JMP ALWAYS COUNTED
    rom[147] = 31'h00000016;   // SETTLED: NOP
    rom[148] = 31'h084b0000;   // LOAD T1
    rom[149] = 31'h01000100;   // HALF 4
    rom[150] = 31'h02c18040;   // FRESH: FLAG STALE 1
    rom[151] = 31'h0000001c;   // MEAN: NOP
    rom[152] = 31'h008e0000;   // ADD S
    rom[153] = 31'h024e0000;   // STORE S
    rom[154] = 31'h02c20008;   // FLAG ACCEL 0
    rom[155] = 31'h23c40000;   // SIGN C_ONE
    rom[156] = 31'h02800000;   // OUT VELOCITY
    rom[157] = 31'h00000000;   // STEADY: NOP
    rom[158] = 31'h08400000;   // LOAD C_ZERO
    rom[159] = 31'h02488000;   // STORE UPS
    rom[160] = 31'h02490000;   // STORE DOWNS
    rom[161] = 31'h03404640;   // JMP ALWAYS NEXT
    rom[162] = 31'h02c1800b;   // AGREE: FLAG STALE 0
    rom[163] = 31'h08458000;   // LOAD C_SETTLED
    rom[164] = 31'h024c800f;   // STORE RUNS
    rom[165] = 31'h08478010;   // LOAD V1
    rom[166] = 31'h20c80000;   // SUB V2
    rom[167] = 31'h01000040;   // HALF 1
    rom[168] = 31'h03412b15;   // JMP NEG BELOW_V2
    rom[169] = 31'h20ca8000;   // SUB T0
    rom[170] = 31'h0341ae00;   // JMP NOT_NEG FIT
    rom[171] = 31'h03402bc0;   // JMP ALWAYS AGREED
    rom[172] = 31'h00000015;   // BELOW_V2: NOP
    rom[173] = 31'h008a8000;   // ADD T0
    rom[174] = 31'h03412e00;   // JMP NEG FIT
    rom[175] = 31'h0000000f;   // AGREED: NOP
    rom[176] = 31'h08478010;   // LOAD V1
    rom[177] = 31'h00880000;   // ADD V2
    rom[178] = 31'h01000040;   // HALF 1
    rom[179] = 31'h024e0000;   // STORE S
    rom[180] = 31'h02c20008;   // FLAG ACCEL 0
    rom[181] = 31'h23c40000;   // SIGN C_ONE
    rom[182] = 31'h02800000;   // OUT VELOCITY
    rom[183] = 31'h03402740;   // JMP ALWAYS STEADY
    rom[184] = 31'h00000013;   // FIT: NOP
    rom[185] = 31'h08498014;   // LOAD P1
    rom[186] = 31'h008a0000;   // ADD P2
    rom[187] = 31'h024b000f;   // STORE T1
    rom[188] = 31'h08478010;   // LOAD V1
    rom[189] = 31'h20c80000;   // SUB V2
    rom[190] = 31'h03413500;   // JMP NEG SLOWER
    rom[191] = 31'h08400000;   // LOAD C_ZERO
    rom[192] = 31'h02490011;   // STORE DOWNS
    rom[193] = 31'h08488008;   // LOAD UPS
    rom[194] = 31'h20c40000;   // SUB C_ONE
    rom[195] = 31'h03413408;   // JMP NEG FIRST_UP
    rom[196] = 31'h20c40000;   // SUB C_ONE
    rom[197] = 31'h024b8009;   // STORE T2
    rom[198] = 31'h08448000;   // LOAD C_TWO
    rom[199] = 31'h0248800f;   // STORE UPS
    rom[200] = 31'h08478010;   // LOAD V1
    rom[201] = 31'h20c80000;   // SUB V2
    rom[202] = 31'h01400016;   // NUM
    rom[203] = 31'h618b09c0;   // DIV T1 39
    rom[204] = 31'h06000000;   // QUOT
    rom[205] = 31'h024a8000;   // STORE T0
    rom[206] = 31'h01000180;   // HALF 6
    rom[207] = 31'h03403ac0;   // JMP ALWAYS EXTRAPOLATE
    rom[208] = 31'h00000008;   // FIRST_UP: NOP
    rom[209] = 31'h08440000;   // LOAD C_ONE
    rom[210] = 31'h02488000;   // STORE UPS
    rom[211] = 31'h034044c0;   // JMP ALWAYS JUMPED
    rom[212] = 31'h00000000;   // SLOWER: NOP
    rom[213] = 31'h08400000;   // LOAD C_ZERO
    rom[214] = 31'h02488012;   // STORE UPS
    rom[215] = 31'h08490008;   // LOAD DOWNS
    rom[216] = 31'h20c40000;   // SUB C_ONE
    rom[217] = 31'h03414408;   // JMP NEG FIRST_DOWN
    rom[218] = 31'h20c40000;   // SUB C_ONE
    rom[219] = 31'h024b8009;   // STORE T2
    rom[220] = 31'h08448000;   // LOAD C_TWO
    rom[221] = 31'h02490010;   // STORE DOWNS
    rom[222] = 31'h0848000f;   // LOAD V2
    rom[223] = 31'h20c78000;   // SUB V1
    rom[224] = 31'h01400016;   // NUM
    rom[225] = 31'h618b09c0;   // DIV T1 39
    rom[226] = 31'h06000000;   // QUOT
    rom[227] = 31'h024a8000;   // STORE T0
    rom[228] = 31'h01000180;   // HALF 6
    rom[229] = 31'h024b0000;   // STORE T1
    rom[230] = 31'h08400015;   // LOAD C_ZERO
    rom[231] = 31'h20ca8000;   // SUB T0
    rom[232] = 31'h024a8000;   // STORE T0
    rom[233] = 31'h08400016;   // LOAD C_ZERO
    rom[234] = 31'h20cb0000;   // SUB T1
    rom[235] = 31'h024b0013;   // EXTRAPOLATE: STORE T1
    rom[236] = 31'h08498000;   // LOAD P1
    rom[237] = 31'h01000046;   // HALF 1
    rom[238] = 31'h00830000;   // ADD C_LATENCY
    rom[239] = 31'h01400016;   // NUM
    rom[240] = 31'h51cb080f;   // MUL T1 32
    rom[241] = 31'h00878000;   // ADD V1
    rom[242] = 31'h024b0017;   // STORE T1
    rom[243] = 31'h084b8000;   // LOAD T2
    rom[244] = 31'h0341bdc0;   // JMP NOT_NEG WAIT
    rom[245] = 31'h08400000;   // LOAD C_ZERO
    rom[246] = 31'h024a8000;   // STORE T0
    rom[247] = 31'h00000016;   // WAIT: NOP
    rom[248] = 31'h084b0000;   // LOAD T1
    rom[249] = 31'h034140c0;   // JMP NEG ZERO
    rom[250] = 31'h03803f00;   // WAIT 252
    rom[251] = 31'h024e0008;   // STORE S
    rom[252] = 31'h23c40000;   // SIGN C_ONE
    rom[253] = 31'h02800015;   // OUT VELOCITY
    rom[254] = 31'h084a8000;   // LOAD T0
    rom[255] = 31'h024e8000;   // STORE A
    rom[256] = 31'h02c28040;   // FLAG TICK 1
    rom[257] = 31'h02c20040;   // FLAG ACCEL 1
    rom[258] = 31'h03404640;   // JMP ALWAYS NEXT
    rom[259] = 31'h00000000;   // ZERO: NOP
    rom[260] = 31'h08400000;   // LOAD C_ZERO
    rom[261] = 31'h024e0000;   // STORE S
    rom[262] = 31'h02c20000;   // FLAG ACCEL 0
    rom[263] = 31'h02800000;   // OUT VELOCITY
    rom[264] = 31'h03404640;   // JMP ALWAYS NEXT
    rom[265] = 31'h0000000b;   // FIRST: NOP
    rom[266] = 31'h08458000;   // LOAD C_SETTLED
    rom[267] = 31'h024c8000;   // STORE RUNS
    rom[268] = 31'h08400000;   // LOAD C_ZERO
    rom[269] = 31'h02488000;   // STORE UPS
    rom[270] = 31'h02490000;   // STORE DOWNS
    rom[271] = 31'h02c08040;   // FLAG HAVE 1
    rom[272] = 31'h00000008;   // FIRST_DOWN: NOP
    rom[273] = 31'h08440000;   // LOAD C_ONE
    rom[274] = 31'h02490000;   // STORE DOWNS
    rom[275] = 31'h0000000f;   // JUMPED: NOP
    rom[276] = 31'h08478000;   // LOAD V1
    rom[277] = 31'h024e0000;   // STORE S
    rom[278] = 31'h02c20008;   // FLAG ACCEL 0
    rom[279] = 31'h23c40000;   // SIGN C_ONE
    rom[280] = 31'h02800000;   // OUT VELOCITY
    rom[281] = 31'h0000000f;   // NEXT: NOP
    rom[282] = 31'h08478000;   // LOAD V1
    rom[283] = 31'h02480013;   // STORE V2
    rom[284] = 31'h08498000;   // LOAD P1
    rom[285] = 31'h024a0000;   // STORE P2
    rom[286] = 31'h03404980;   // JMP ALWAYS DONE
    rom[287] = 31'h00000021;   // ANCHOR: NOP
    rom[288] = 31'h08608000;   // LOAD s.STIME
    rom[289] = 31'h02468022;   // STORE W_TIME
    rom[290] = 31'h08610000;   // LOAD s.SPOSC
    rom[291] = 31'h02470000;   // STORE W_POSC
    rom[292] = 31'h02c00040;   // FLAG ANCH 1
    rom[293] = 31'h02c08000;   // FLAG HAVE 0
    rom[294] = 31'h03000000;   // DONE: DONE
    rom[295] = 31'h03400000;   // JMP ALWAYS IDLE
    rom[296] = 31'h024e0000;   // RESTART: STORE S
    rom[297] = 31'h02c20000;   // FLAG ACCEL 0
    rom[298] = 31'h02c00000;   // FLAG ANCH 0
    rom[299] = 31'h02c08000;   // FLAG HAVE 0
    rom[300] = 31'h02c10000;   // FLAG BND 0
    rom[301] = 31'h03400000;   // JMP ALWAYS IDLE
  end

  always @(posedge clk) begin
    word <= rom[pc];
  end

endmodule

`resetall
