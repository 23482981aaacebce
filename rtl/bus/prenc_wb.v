// SPDX-License-Identifier: Apache-2.0
// prenc_wb: the reader core on a Wishbone B4 bus (32-bit data), with its register map.
//
// The map is rtl/bus/prenc_wb.rdl (SystemRDL); docs/registers.md and sw/prenc_wb.h are
// generated from it (scripts/regmap.py), and tb/lint/test_regmap.py checks that the
// addresses below are the RDL's. In short (byte offsets):
//   0x00 ID 'prnc'        0x04 VERSION          0x08 PARAMS (N, FILTER)
//   0x0C CTRL             resolution (rw, reset 1), clear_errors, snapshot (write 1)
//   0x10 STATUS           valid, mode, direction, track1_valid, track2_valid,
//                         velocity_valid, the warnings (head 1, head 2, sync)
//   0x14 POSITION         pos_abs or pos_hyb as CTRL.resolution selects
//   0x18 POS_ABS  0x1C POS_HYB  0x20 INCREMENTAL  0x24 TRACK1  0x28 TRACK2
//   0x2C TRACK_ERRORS (track 2 << 16 | track 1)   0x30 SYNC_ERRORS   0x34 TIMESTAMP
//   0x38 IRQ_STATUS (write 1 to clear)   0x3C IRQ_ENABLE
//   0x40 SNAP_POS_HYB  0x44 SNAP_STATUS  0x48 SNAP_INCREMENTAL  0x4C SNAP_TIME
//   0x50 FINE_POS  0x54 VELOCITY  0x58 SNAP_FINE_POS  0x5C SNAP_VELOCITY
//   0x60 CAL_ADDR  0x64 CAL_DATA (the calibration table, CAL = 1)
//
// Bus: classic Wishbone B4 slave, word addresses (wb_adr_i = byte offset / 4, as
// LiteX's bus), one access per three clocks: ack one clock after cyc & stb, with the
// read data. Writes honour wb_sel_i[0] (every writable field is in byte 0); other
// offsets up to 0x7C read 0 and ignore writes. wb_err_o is never raised.
//
// Snapshot: writing CTRL.snapshot = 1 latches pos_hyb, STATUS, INCREMENTAL, TIMESTAMP,
// FINE_POS and VELOCITY on one clock (the clock the write is acknowledged), so that they
// belong together however long the reads that follow take.
//
// Fine position and velocity (prenc_fine, docs/fine.md; FINE = 1): FINE_POS is the
// hybrid position with FINE_BITS more bits, extrapolated (EXTRAPOLATE = 1) so that the
// snapshot holds the fine position of the clock its write was sampled
// (LOOKAHEAD_HALVES = 2 (10 + FILTER + 4 CAL) - 1: with CAL = 1 prenc_fine's table takes
// 4 clocks; a live read is one clock older). VELOCITY is
// prenc_velocity's in quarters per clock x 2^32, signed, saturating at 32 bits.
//
// Calibration table (CAL = 1, docs/calibration.md): a write to CAL_DATA writes its bits
// 15:0 into the table's word CAL_ADDR (modulo the table's 4 x 2^N words; it counts from
// the next clock) and adds 1 to CAL_ADDR: load a table with CAL_ADDR = 0, then its words
// in order. CAL_ADDR and CAL_DATA take whole words (wb_sel_i[0] as for the others).
//
// Interrupt: IRQ_STATUS.lost_valid is set when pos_valid falls, .mode_change when mode
// changes, .warning when prenc_health's warning rises (an event beats a clear on the
// same clock); irq = |(IRQ_STATUS & IRQ_ENABLE).
//
// Warning (prenc_health, docs/health.md): STATUS.warn_track1, warn_track2, warn_sync, each
// source's warning: its corrections come more often than one per WARN_SLOTS slots of
// travel (128), or WARN_BURST (8) at once.
//
// Latency: ack one clock after cyc & stb; a read returns the register as it was on the
// clock the access was sampled. The core's outputs are 6 + FILTER clocks behind the
// pins (prenc_core).
//
// Parameters: those of prenc_core (N, TAPS, FILTER, ROM_FILE, and its decision and build
// options LOCK_BOTH, LOCK_ONE, LOCK_EXTRA, DUAL_VOTES, DUAL_SPAN, HYPOTHESES, SCORE_UP,
// SCORE_LIMIT, CONV_REG, passed to it as they are; the counters are 32-bit and 16-bit,
// as the map), checked there; N <= 24 fits the map's fields. FINE (1: prenc_fine is
// built; 0: not, FINE_POS reads POS_HYB and VELOCITY 0), FINE_BITS (0..8, default 8;
// N + 2 + FINE_BITS <= 32, 0 with FINE = 0), EXTRAPOLATE (1), VELOCITY_WINDOW (the
// velocity's window, 34 us in clocks: 1024 at 30 MHz, the default; docs/fine.md),
// CAL (1: the calibration table, with FINE = 1 and N <= 16; 0: not, default) and
// CAL_FILE (the table it starts with; "" : all zero); EDGE_TOLERANCE (how far the
// edges may be off their places: prenc_velocity's, docs/fine.md); WARN_SLOTS, WARN_BURST
// (prenc_health's).

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_wb #(
  parameter integer N           = 10,
  parameter [31:0]  TAPS        = 32'h0000_0204,
  parameter integer FILTER      = 2,
  parameter         ROM_FILE    = "prenc_rom_n10.hex",
  parameter integer LOCK_BOTH   = (N < 8) ? 3 : 2,
  parameter integer LOCK_ONE    = (N < 8) ? N + 5 : N + 2,
  parameter integer LOCK_EXTRA  = 3,
  parameter integer DUAL_VOTES  = 3,
  parameter integer DUAL_SPAN   = 12,
  parameter integer HYPOTHESES  = 1,
  parameter integer SCORE_UP    = 4,
  parameter integer SCORE_LIMIT = 12,
  parameter integer CONV_REG    = 0,
  parameter integer FINE            = 1,
  parameter integer FINE_BITS       = (FINE == 1) ? 8 : 0,
  parameter integer EXTRAPOLATE     = 1,
  parameter integer VELOCITY_WINDOW = 1024,
  parameter integer CAL             = 0,
  parameter         CAL_FILE        = "",
  parameter integer EDGE_TOLERANCE  = 0,
  parameter integer WARN_SLOTS      = 128,
  parameter integer WARN_BURST      = 8
) (
  input  wire         clk,
  input  wire         rst,
  // The encoder's pins (asynchronous).
  input  wire         head1,
  input  wire         head2,
  input  wire         sync_a,
  input  wire         sync_b,
  // Wishbone B4 classic slave.
  input  wire         wb_cyc_i,
  input  wire         wb_stb_i,
  input  wire         wb_we_i,
  input  wire [4:0]   wb_adr_i,
  input  wire [31:0]  wb_dat_i,
  input  wire [3:0]   wb_sel_i,
  output reg  [31:0]  wb_dat_o,
  output reg          wb_ack_o,
  output wire         wb_err_o,
  // Interrupt, level, active high.
  output wire         irq,
  // The position for logic beside the bus (the core's outputs).
  output wire [N+1:0] pos_hyb,
  output wire         pos_valid
);

  // Word addresses of the map (checked against prenc_wb.rdl by tb/lint/test_regmap.py).
  localparam [4:0] A_ID               = 5'h00;
  localparam [4:0] A_VERSION          = 5'h01;
  localparam [4:0] A_PARAMS           = 5'h02;
  localparam [4:0] A_CTRL             = 5'h03;
  localparam [4:0] A_STATUS           = 5'h04;
  localparam [4:0] A_POSITION         = 5'h05;
  localparam [4:0] A_POS_ABS          = 5'h06;
  localparam [4:0] A_POS_HYB          = 5'h07;
  localparam [4:0] A_INCREMENTAL      = 5'h08;
  localparam [4:0] A_TRACK1           = 5'h09;
  localparam [4:0] A_TRACK2           = 5'h0A;
  localparam [4:0] A_TRACK_ERRORS     = 5'h0B;
  localparam [4:0] A_SYNC_ERRORS      = 5'h0C;
  localparam [4:0] A_TIMESTAMP        = 5'h0D;
  localparam [4:0] A_IRQ_STATUS       = 5'h0E;
  localparam [4:0] A_IRQ_ENABLE       = 5'h0F;
  localparam [4:0] A_SNAP_POS_HYB     = 5'h10;
  localparam [4:0] A_SNAP_STATUS      = 5'h11;
  localparam [4:0] A_SNAP_INCREMENTAL = 5'h12;
  localparam [4:0] A_SNAP_TIME        = 5'h13;
  localparam [4:0] A_FINE_POS         = 5'h14;
  localparam [4:0] A_VELOCITY         = 5'h15;
  localparam [4:0] A_SNAP_FINE_POS    = 5'h16;
  localparam [4:0] A_SNAP_VELOCITY    = 5'h17;
  localparam [4:0] A_CAL_ADDR         = 5'h18;
  localparam [4:0] A_CAL_DATA         = 5'h19;

  localparam [31:0] ID      = 32'h7072_6E63;  // "prnc"
  localparam [31:0] VERSION = 32'h0000_1600;  // 0.22.0, the project's VERSION

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d out of range 2..24 (the map's fields)", N);
      prenc_wb_parameter_N_out_of_range_2_to_24 u_stop ();
    end
    if (FINE < 0 || FINE > 1) begin : g_bad_fine
      initial $display("ERROR: %m: parameter FINE = %0d must be 0 or 1", FINE);
      prenc_wb_parameter_FINE_must_be_0_or_1 u_stop ();
    end
    if (N + 2 + FINE_BITS > 32 || (FINE == 0 && FINE_BITS != 0)) begin : g_bad_fine_bits
      initial $display("ERROR: %m: parameter FINE_BITS = %0d (N + 2 + it <= 32; 0 with FINE = 0)",
                       FINE_BITS);
      prenc_wb_parameter_FINE_BITS_out_of_range u_stop ();
    end
    if (CAL != 0 && (CAL != 1 || FINE != 1 || N > 16)) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0, or 1 with FINE = 1 and N <= 16",
                       CAL);
      prenc_wb_parameter_CAL_must_be_0_or_1_with_FINE_1 u_stop ();
    end
    if (EXTRAPOLATE < 0 || EXTRAPOLATE > 1) begin : g_bad_extrapolate
      initial $display("ERROR: %m: parameter EXTRAPOLATE = %0d must be 0 or 1", EXTRAPOLATE);
      prenc_wb_parameter_EXTRAPOLATE_must_be_0_or_1 u_stop ();
    end
    if (FILTER < 0 || FILTER > 65535) begin : g_bad_filter
      initial $display("ERROR: %m: parameter FILTER = %0d out of range 0..65535", FILTER);
      prenc_wb_parameter_FILTER_out_of_range_0_to_65535 u_stop ();
    end
  endgenerate

  // Control.
  reg        resolution;
  reg        clear_errors;
  reg        snapshot;
  reg [2:0]  irq_status;   // {warning, mode_change, lost_valid}
  reg [2:0]  irq_enable;
  reg [31:0] timestamp;

  // The core.
  wire [N-1:0]  pos_abs;
  wire [2:0]    mode;
  wire [N+1:0]  position;
  wire [31:0]   incremental;
  wire          direction;
  wire [N-1:0]  track1_pos;
  wire          track1_valid;
  wire [N-1:0]  track2_pos;
  wire          track2_valid;
  wire [15:0]   track1_errors;
  wire [15:0]   track2_errors;
  wire [15:0]   sync_errors;
  wire          track1_error;
  wire          track2_error;
  wire          sync_step;
  wire          sync_illegal;

  // The warning before a failure.
  wire [2:0] warnings;
  wire       warning;

  prenc_health #(
    .WARN_SLOTS (WARN_SLOTS),
    .WARN_BURST (WARN_BURST)
  ) u_health (
    .clk          (clk),
    .rst          (rst),
    .step         (sync_step),
    .track1_error (track1_error),
    .track2_error (track2_error),
    .sync_illegal (sync_illegal),
    .warnings     (warnings),
    .warning      (warning)
  );

  prenc_core #(
    .N           (N),
    .TAPS        (TAPS),
    .FILTER      (FILTER),
    .ROM_FILE    (ROM_FILE),
    .COUNT_WIDTH (32),
    .ERROR_WIDTH (16),
    .LOCK_BOTH   (LOCK_BOTH),
    .LOCK_ONE    (LOCK_ONE),
    .LOCK_EXTRA  (LOCK_EXTRA),
    .DUAL_VOTES  (DUAL_VOTES),
    .DUAL_SPAN   (DUAL_SPAN),
    .HYPOTHESES  (HYPOTHESES),
    .SCORE_UP    (SCORE_UP),
    .SCORE_LIMIT (SCORE_LIMIT),
    .CONV_REG    (CONV_REG)
  ) u_core (
    .clk           (clk),
    .rst           (rst),
    .head1         (head1),
    .head2         (head2),
    .sync_a        (sync_a),
    .sync_b        (sync_b),
    .resolution    (resolution),
    .clear_errors  (clear_errors),
    .pos_abs       (pos_abs),
    .pos_hyb       (pos_hyb),
    .pos_valid     (pos_valid),
    .mode          (mode),
    .position      (position),
    .incremental   (incremental),
    .direction     (direction),
    .track1_pos    (track1_pos),
    .track1_valid  (track1_valid),
    .track2_pos    (track2_pos),
    .track2_valid  (track2_valid),
    .track1_errors (track1_errors),
    .track2_errors (track2_errors),
    .sync_errors   (sync_errors),
    .track1_error  (track1_error),
    .track2_error  (track2_error),
    .sync_step     (sync_step),
    .sync_illegal  (sync_illegal)
  );

  // Fine position and velocity.
  localparam integer W         = N + 2 + FINE_BITS;
  localparam integer LOOKAHEAD = (EXTRAPOLATE == 1) ? 2 * (10 + FILTER + 4 * CAL) - 1 : 0;
  wire [W-1:0] fine_pos;
  wire         fine_valid;
  wire         interpolated;
  wire [31:0]  velocity;       // quarters per clock x 2^32, signed
  wire         velocity_valid;

  // The calibration table's writes (CAL_DATA), a clock after the bus write.
  reg  [17:0]  cal_addr;
  reg          cal_write;
  reg  [N+1:0] cal_address;
  reg  [15:0]  cal_data;

  prenc_fine #(
    .N                (N),
    .FINE_BITS        (FINE_BITS),
    .LOOKAHEAD_HALVES (LOOKAHEAD),
    .WINDOW           (VELOCITY_WINDOW),
    .ENABLE           (FINE),
    .CAL              (CAL),
    .CAL_FILE         (CAL_FILE),
    .EDGE_TOLERANCE   (EDGE_TOLERANCE)
  ) u_fine (
    .clk            (clk),
    .rst            (rst),
    .pos_hyb        (pos_hyb),
    .pos_valid      (pos_valid),
    .step           (sync_step),
    .step_cw        (direction),
    .illegal        (sync_illegal),
    .cal_write      (cal_write),
    .cal_address    (cal_address),
    .cal_data       (cal_data),
    .fine_pos       (fine_pos),
    .fine_valid     (fine_valid),
    .interpolated   (interpolated),
    .velocity       (velocity),
    .velocity_valid (velocity_valid)
  );

  wire [10:0] status = {warnings, velocity_valid, track2_valid, track1_valid, direction, mode,
                        pos_valid};

  // Bus access: one acknowledged access per cyc & stb, ack for one clock.
  wire access = wb_cyc_i & wb_stb_i & ~wb_ack_o;
  wire write0 = access & wb_we_i & wb_sel_i[0];

  // Events of the interrupt.
  reg       last_valid;
  reg [2:0] last_mode;
  reg       last_warning;
  wire [2:0] events = {warning & ~last_warning, mode != last_mode, last_valid & ~pos_valid};

  // Snapshot registers.
  reg [N+1:0] snap_pos_hyb;
  reg [10:0]  snap_status;
  reg [31:0]  snap_incremental;
  reg [31:0]  snap_time;
  reg [W-1:0] snap_fine_pos;
  reg [31:0]  snap_velocity;

  always @(posedge clk) begin
    if (rst) begin
      resolution   <= 1'b1;
      clear_errors <= 1'b0;
      snapshot     <= 1'b0;
      irq_status   <= 3'b000;
      irq_enable   <= 3'b000;
      timestamp    <= 32'd0;
      last_valid   <= 1'b0;
      last_mode    <= 3'd0;
      last_warning <= 1'b0;
      wb_ack_o     <= 1'b0;
      cal_addr     <= 18'd0;
      cal_write    <= 1'b0;
    end else begin
      timestamp    <= timestamp + 1'b1;
      last_valid   <= pos_valid;
      last_mode    <= mode;
      last_warning <= warning;
      wb_ack_o     <= access;
      clear_errors <= write0 && wb_adr_i == A_CTRL && wb_dat_i[1];
      snapshot     <= write0 && wb_adr_i == A_CTRL && wb_dat_i[2];
      if (write0 && wb_adr_i == A_CTRL) resolution <= wb_dat_i[0];
      if (write0 && wb_adr_i == A_IRQ_ENABLE) irq_enable <= wb_dat_i[2:0];
      cal_write <= (CAL == 1) && write0 && wb_adr_i == A_CAL_DATA;
      if (write0 && wb_adr_i == A_CAL_DATA) begin
        cal_address <= cal_addr[N+1:0];
        cal_data    <= wb_dat_i[15:0];
        cal_addr    <= cal_addr + 18'd1;
      end
      if (write0 && wb_adr_i == A_CAL_ADDR) cal_addr <= wb_dat_i[17:0];
      if (write0 && wb_adr_i == A_IRQ_STATUS) begin
        irq_status <= (irq_status & ~wb_dat_i[2:0]) | events;
      end else begin
        irq_status <= irq_status | events;
      end
    end
  end

  // The snapshot: everything from the clock after the write, together.
  always @(posedge clk) begin
    if (rst) begin
      snap_pos_hyb     <= {N+2{1'b0}};
      snap_status      <= 11'd0;
      snap_incremental <= 32'd0;
      snap_time        <= 32'd0;
      snap_fine_pos    <= {W{1'b0}};
      snap_velocity    <= 32'd0;
    end else if (snapshot) begin
      snap_pos_hyb     <= pos_hyb;
      snap_status      <= status;
      snap_incremental <= incremental;
      snap_time        <= timestamp;
      snap_fine_pos    <= fine_pos;
      snap_velocity    <= velocity;
    end
  end

  wire [31:0] fine_word;
  wire [31:0] snap_fine_word;
  generate
    if (W < 32) begin : g_fine_word
      assign fine_word      = {{(32 - W){1'b0}}, fine_pos};
      assign snap_fine_word = {{(32 - W){1'b0}}, snap_fine_pos};
    end else begin : g_fine_word_full
      assign fine_word      = fine_pos;
      assign snap_fine_word = snap_fine_pos;
    end
  endgenerate

  // Read data, registered with ack.
  always @(posedge clk) begin
    if (access) begin
      case (wb_adr_i)
        A_ID:               wb_dat_o <= ID;
        A_VERSION:          wb_dat_o <= VERSION;
        A_PARAMS:           wb_dat_o <= {FILTER[15:0], 5'd0, CAL[0], FINE[0], FINE_BITS[3:0],
                                         N[4:0]};
        A_CTRL:             wb_dat_o <= {31'd0, resolution};
        A_STATUS:           wb_dat_o <= {21'd0, status};
        A_POSITION:         wb_dat_o <= {{(30 - N){1'b0}}, position};
        A_POS_ABS:          wb_dat_o <= {{(32 - N){1'b0}}, pos_abs};
        A_POS_HYB:          wb_dat_o <= {{(30 - N){1'b0}}, pos_hyb};
        A_INCREMENTAL:      wb_dat_o <= incremental;
        A_TRACK1:           wb_dat_o <= {track1_valid, {(31 - N){1'b0}}, track1_pos};
        A_TRACK2:           wb_dat_o <= {track2_valid, {(31 - N){1'b0}}, track2_pos};
        A_TRACK_ERRORS:     wb_dat_o <= {track2_errors, track1_errors};
        A_SYNC_ERRORS:      wb_dat_o <= {16'd0, sync_errors};
        A_TIMESTAMP:        wb_dat_o <= timestamp;
        A_IRQ_STATUS:       wb_dat_o <= {29'd0, irq_status};
        A_IRQ_ENABLE:       wb_dat_o <= {29'd0, irq_enable};
        A_SNAP_POS_HYB:     wb_dat_o <= {{(30 - N){1'b0}}, snap_pos_hyb};
        A_SNAP_STATUS:      wb_dat_o <= {21'd0, snap_status};
        A_SNAP_INCREMENTAL: wb_dat_o <= snap_incremental;
        A_SNAP_TIME:        wb_dat_o <= snap_time;
        A_FINE_POS:         wb_dat_o <= fine_word;
        A_VELOCITY:         wb_dat_o <= velocity;
        A_SNAP_FINE_POS:    wb_dat_o <= snap_fine_word;
        A_SNAP_VELOCITY:    wb_dat_o <= snap_velocity;
        A_CAL_ADDR:         wb_dat_o <= (CAL == 1) ? {14'd0, cal_addr} : 32'd0;
        default:            wb_dat_o <= 32'd0;
      endcase
    end
  end

  assign wb_err_o = 1'b0;
  wire unused_ok = &{1'b0, wb_sel_i[3:1], wb_dat_i[31:18], sync_step, sync_illegal, fine_valid,
                     interpolated};
  assign irq      = |(irq_status & irq_enable);

endmodule

`resetall
