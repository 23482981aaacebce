// SPDX-License-Identifier: Apache-2.0
// prenc_board: the reader as it goes on a board, without the board's clock and pins.
//
//   encoder pins -> prenc_core -> prenc_host_link (UART to the PC, docs/host-protocol.md)
//                             -> prenc_edge_capture (the edges' timing, for calibration)
//                             -> prenc_fine (fine position, velocity; docs/fine.md)
//                                -> prenc_turns -> prenc_ssi  (SSI to a motion controller)
//                                               -> prenc_biss (BiSS-C to a servo drive)
//                                               -> prenc_as5047 (SPI, as the AS5047P)
//                                               -> prenc_abi, prenc_uvw (A/B/I, U/V/W)
//                             -> prenc_health (the warning: BiSS-C's nW, the SPI's MAGL,
//                                the host link's FLAGS; docs/health.md)
//                             -> mode LEDs
//
// SSI and BiSS-C send the fine position, N + 2 + FINE_BITS bits, extrapolated to the
// master's first falling clock edge (EXTRAPOLATE = 1); the SPI its top 14 bits (prenc_fine
// makes at least 14: FINE_BITS or 12 - N more, of which SSI and BiSS-C drop the last),
// extrapolated to CSn's falling edge. The pins reach the fine output
// in 2 + FILTER + 1 + 4 + 3 clocks (4 more with CAL = 1: prenc_fine's table), half a
// clock after the edge on average. The frame latches the fine output of the clock that
// first samples the master's edge (its synchronizer and prenc_turns' register take the
// two clocks to the latch), half a clock after that edge on average: LOOKAHEAD_HALVES
// = 2 (10 + FILTER + 4 CAL). All three take the fine position from prenc_turns'
// register, so turns and position are always one pair, and the SPI's CSn passes the
// same synchronizer.
//
// The board tops in constraints/<board>/ add the PLL, the power-on reset and the
// pin names; this module is what the tests simulate (tb/prenc_board).
//
// Latency: the core's 6 + FILTER clocks from the pins to pos_hyb; the fine position and
// velocity as prenc_fine; the SSI and BiSS-C frames send the fine position extrapolated
// to the master's first falling edge (above), and the host link's answers the outputs
// of the clock their frame starts.
//
// Parameters
//   N, TAPS, FILTER, ROM_FILE   as prenc_core (N here 4..16: the link sends 2 bytes)
//   CLK_HZ        clock frequency, a multiple of 1 MHz
//   BAUD          UART baud rate (default 115200; CLK_HZ / BAUD >= 4, within 2 %)
//   SSI_HYBRID    1: SSI sends pos_hyb (N+2 bits); 0: pos_abs (N bits)
//   SSI_MONOFLOP_US   SSI monoflop time in microseconds (default 20)
//   SSI_WARNING   1: the SSI frame ends with the warning bit after the error bit (1: the
//                 warning; docs/health.md); 0: position and error bit only (default)
//   BISS_MT_BITS  BiSS-C multi-turn bits, 0..24 (default 12; 0: single-turn only)
//   BISS_HYBRID   1: BiSS-C single-turn is pos_hyb (N+2 bits); 0: pos_abs (N bits)
//   BISS_TIMEOUT_US   BiSS-C timeout in microseconds (default 20; longer than half a
//                 period of the slowest MA). MA up to CLK_HZ / 5 (docs/biss-c.md)
//   BISS_ST_BITS  0: the single-turn field is BISS_HYBRID's (default); 8..40: that many
//                 bits, the fine position's top ones (zeros below), for a master that
//                 knows only fixed layouts (docs/biss-c.md: OnStepX's, VESC's)
//   BISS_ERROR_HIGH   0: the error bit nE is 0 on an error (BiSS-C's, default); 1: it is
//                 1 (the Broadcom AS37-H39B's, as OnStepX reads it)
//   SPI           1: the AS5047P-compatible SPI slave is built (default); 0: not
//                 (spi_miso_oe is 0). SCLK up to 10 MHz at 30 MHz (prenc_as5047)
//   SPI_ZERO, SPI_SETTINGS1, SPI_SETTINGS2   its zero and settings after reset
//                 (prenc_as5047's ZERO, SETTINGS1, SETTINGS2: 0, 0x01, 0x00); with SPI = 0
//                 the zero and settings that ABI and UVW keep
//   ABI           1: A/B quadrature and the index are built (prenc_abi; default); 0: not
//   ABI_STEPS     steps per turn, a multiple of 4 up to 2^15;
//                 0: the AS5047P's ABIRES and ABIBIN (default 0: 4000 steps)
//   ABI_EDGE_NS   the shortest time between two edges of A and B (default 250 ns)
//   UVW           1: U, V, W commutation signals are built (prenc_uvw; default); 0: not
//   UVW_POLE_PAIRS  0: the AS5047P's UVWPP (default 0: 1 pole pair); else 1..32
//   HOST_LINK     1: the host link and the edges' capture are built (default); 0: not
//                 (uart_tx idles high, uart_rx is unused, the error counters are never
//                 cleared: the iCEstick's HX1K has no room for the link's ~1,000 cells)
//   EDGE_CAPTURE  1: with the host link, the edges' capture for a calibration run
//                 (`prenc calibrate`; default); 0: not (the EDGES answer has no run: the
//                 iCEBreaker's UP5K keeps its ~500 cells for prenc_fine)
//   FINE          1: prenc_fine is built (fine position, velocity; default); 0: not (SSI
//                 and BiSS-C send pos_hyb: the iCEBreaker's UP5K has no room for it)
//   FINE_BITS     fraction bits of the quarter in SSI's and BiSS-C's position, 0..8
//                 (default 0: the quarter, as pos_hyb)
//   EXTRAPOLATE   1: SSI's and BiSS-C's position is extrapolated by the velocity to the
//                 master's request (default); 0: the position as the pipeline has it
//   CAL           1: the fine position and the velocity use the sync track's calibration
//                 table (docs/calibration.md; needs FINE = 1), written over the host
//                 link (WRITE_CAL) or built in from CAL_FILE; 0: the nominal edges (default)
//   CAL_FILE      with CAL = 1: the table ($readmemh, prenc.cal.table's format, checked in
//                 simulation); "" : all zero until written
//   EDGE_TOLERANCE  how far the edges may be off their places (nominal, or with CAL = 1
//                 the table's: a printed disc without its table, a noisy sensor), 1/1000
//                 slot, 0..60 (docs/fine.md; default 0: exact)
//   HEALTH        1: the warning before a failure is built (prenc_health; default); 0:
//                 not (nW only in a reduced mode: the iCEstick's HX1K has no room)
//   WARN_SLOTS, WARN_BURST   prenc_health's: a source warns when its corrections come
//                 more often than one per WARN_SLOTS slots of travel (128) or WARN_BURST
//                 (8) at once
//   LOCK_BOTH, LOCK_ONE, LOCK_EXTRA, DUAL_VOTES, DUAL_SPAN, HYPOTHESES, SCORE_UP,
//   SCORE_LIMIT, CONV_REG   the core's decision and build options, passed to it as
//                 they are (prenc_core's header: ranges and defaults; checked there)
//
// Ports
//   clk, rst                       one clock; synchronous active-high reset (>= 4 clocks)
//   head1, head2, sync_a, sync_b   the encoder's outputs (asynchronous)
//   uart_rx, uart_tx               the host link
//   ssi_clk, ssi_data, ssi_gray    SSI: clock from the controller, data, 1 = Gray code
//   biss_ma, biss_slo              BiSS-C: clock from the master, data to it (SSI,
//                                  BiSS-C and SPI are all built, on their own pins)
//   spi_csn, spi_sclk, spi_mosi, spi_miso, spi_miso_oe   the SPI (MISO is driven while
//                                  spi_miso_oe is 1: a tristate on the board's pin)
//   abi_a, abi_b, abi_i            A/B quadrature and the index (docs/interfaces/abi-uvw.md)
//   uvw_u, uvw_v, uvw_w            U, V, W
//   led_valid                      pos_valid
//   led_normal, led_reduced, led_incremental, led_acquire   the mode, one-hot
//   pos_valid, mode                the core's, for test benches and debug headers

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_board #(
  parameter integer N               = 10,
  parameter [31:0]  TAPS            = 32'h0000_0204,
  parameter integer FILTER          = 2,
  parameter         ROM_FILE        = "prenc_rom_n10.hex",
  parameter integer CLK_HZ          = 24000000,
  parameter integer BAUD            = 115200,
  parameter integer SSI_HYBRID      = 1,
  parameter integer SSI_MONOFLOP_US = 20,
  parameter integer SSI_WARNING     = 0,
  parameter integer BISS_MT_BITS    = 12,
  parameter integer BISS_HYBRID     = 1,
  parameter integer BISS_TIMEOUT_US = 20,
  parameter integer BISS_ST_BITS    = 0,
  parameter integer BISS_ERROR_HIGH = 0,
  parameter integer SPI             = 1,
  parameter integer SPI_ZERO        = 0,
  parameter integer SPI_SETTINGS1   = 1,
  parameter integer SPI_SETTINGS2   = 0,
  parameter integer ABI             = 1,
  parameter integer ABI_STEPS       = 0,
  parameter integer ABI_EDGE_NS     = 250,
  parameter integer UVW             = 1,
  parameter integer UVW_POLE_PAIRS  = 0,
  parameter integer HOST_LINK       = 1,
  parameter integer EDGE_CAPTURE    = 1,
  parameter integer FINE            = 1,
  parameter integer FINE_BITS       = 0,
  parameter integer EXTRAPOLATE     = 1,
  parameter integer CAL             = 0,
  parameter         CAL_FILE        = "",
  parameter integer EDGE_TOLERANCE  = 0,
  parameter integer HEALTH          = 1,
  parameter integer WARN_SLOTS      = 128,
  parameter integer WARN_BURST      = 8,
  parameter integer LOCK_BOTH       = (N < 8) ? 3 : 2,
  parameter integer LOCK_ONE        = (N < 8) ? N + 5 : N + 2,
  parameter integer LOCK_EXTRA      = 3,
  parameter integer DUAL_VOTES      = 3,
  parameter integer DUAL_SPAN       = 12,
  parameter integer HYPOTHESES      = 1,
  parameter integer SCORE_UP        = 4,
  parameter integer SCORE_LIMIT     = 12,
  parameter integer CONV_REG        = 0
) (
  input  wire       clk,
  input  wire       rst,
  input  wire       head1,
  input  wire       head2,
  input  wire       sync_a,
  input  wire       sync_b,
  input  wire       uart_rx,
  output wire       uart_tx,
  input  wire       ssi_clk,
  output wire       ssi_data,
  input  wire       ssi_gray,
  input  wire       biss_ma,
  output wire       biss_slo,
  input  wire       spi_csn,
  input  wire       spi_sclk,
  input  wire       spi_mosi,
  output wire       spi_miso,
  output wire       spi_miso_oe,
  output wire       abi_a,
  output wire       abi_b,
  output wire       abi_i,
  output wire       uvw_u,
  output wire       uvw_v,
  output wire       uvw_w,
  output wire       led_valid,
  output wire       led_normal,
  output wire       led_reduced,
  output wire       led_incremental,
  output wire       led_acquire,
  output wire       pos_valid,
  output wire [2:0] mode
);

  generate
    if (N < 4 || N > 16) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 4..16", N);
      prenc_board_parameter_N_out_of_range_4_to_16 u_stop ();
    end
    if (SSI_HYBRID < 0 || SSI_HYBRID > 1) begin : g_bad_ssi_hybrid
      initial $display("ERROR: %m: parameter SSI_HYBRID = %0d must be 0 or 1", SSI_HYBRID);
      prenc_board_parameter_SSI_HYBRID_must_be_0_or_1 u_stop ();
    end
    if (SSI_MONOFLOP_US < 1 || SSI_MONOFLOP_US > 1000) begin : g_bad_monoflop
      initial $display("ERROR: %m: parameter SSI_MONOFLOP_US = %0d is out of range 1..1000",
                       SSI_MONOFLOP_US);
      prenc_board_parameter_SSI_MONOFLOP_US_out_of_range_1_to_1000 u_stop ();
    end
    if (BISS_MT_BITS < 0 || BISS_MT_BITS > 24) begin : g_bad_biss_mt_bits
      initial $display("ERROR: %m: parameter BISS_MT_BITS = %0d is out of range 0..24",
                       BISS_MT_BITS);
      prenc_board_parameter_BISS_MT_BITS_out_of_range_0_to_24 u_stop ();
    end
    if (BISS_HYBRID < 0 || BISS_HYBRID > 1) begin : g_bad_biss_hybrid
      initial $display("ERROR: %m: parameter BISS_HYBRID = %0d must be 0 or 1", BISS_HYBRID);
      prenc_board_parameter_BISS_HYBRID_must_be_0_or_1 u_stop ();
    end
    if (HOST_LINK < 0 || HOST_LINK > 1) begin : g_bad_host_link
      initial $display("ERROR: %m: parameter HOST_LINK = %0d must be 0 or 1", HOST_LINK);
      prenc_board_parameter_HOST_LINK_must_be_0_or_1 u_stop ();
    end
    if (SSI_WARNING < 0 || SSI_WARNING > 1) begin : g_bad_ssi_warning
      initial $display("ERROR: %m: parameter SSI_WARNING = %0d must be 0 or 1", SSI_WARNING);
      prenc_board_parameter_SSI_WARNING_must_be_0_or_1 u_stop ();
    end
    if (HEALTH < 0 || HEALTH > 1) begin : g_bad_health
      initial $display("ERROR: %m: parameter HEALTH = %0d must be 0 or 1", HEALTH);
      prenc_board_parameter_HEALTH_must_be_0_or_1 u_stop ();
    end
    if (EDGE_CAPTURE < 0 || EDGE_CAPTURE > 1) begin : g_bad_edge_capture
      initial $display("ERROR: %m: parameter EDGE_CAPTURE = %0d must be 0 or 1", EDGE_CAPTURE);
      prenc_board_parameter_EDGE_CAPTURE_must_be_0_or_1 u_stop ();
    end
    if (FINE < 0 || FINE > 1) begin : g_bad_fine
      initial $display("ERROR: %m: parameter FINE = %0d must be 0 or 1", FINE);
      prenc_board_parameter_FINE_must_be_0_or_1 u_stop ();
    end
    if (FINE == 0 && FINE_BITS != 0) begin : g_bad_fine_bits
      initial $display("ERROR: %m: parameter FINE_BITS = %0d needs FINE = 1", FINE_BITS);
      prenc_board_parameter_FINE_BITS_needs_FINE_1 u_stop ();
    end
    if (CAL != 0 && (CAL != 1 || FINE != 1)) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0, or 1 with FINE = 1", CAL);
      prenc_board_parameter_CAL_must_be_0_or_1_with_FINE_1 u_stop ();
    end
    if (EXTRAPOLATE < 0 || EXTRAPOLATE > 1) begin : g_bad_extrapolate
      initial $display("ERROR: %m: parameter EXTRAPOLATE = %0d must be 0 or 1", EXTRAPOLATE);
      prenc_board_parameter_EXTRAPOLATE_must_be_0_or_1 u_stop ();
    end
    if (SPI < 0 || SPI > 1) begin : g_bad_spi
      initial $display("ERROR: %m: parameter SPI = %0d must be 0 or 1", SPI);
      prenc_board_parameter_SPI_must_be_0_or_1 u_stop ();
    end
    if (BISS_ST_BITS != 0 && (BISS_ST_BITS < 8 || BISS_ST_BITS > 40)) begin : g_bad_biss_st_bits
      initial $display("ERROR: %m: parameter BISS_ST_BITS = %0d must be 0 or 8..40", BISS_ST_BITS);
      prenc_board_parameter_BISS_ST_BITS_must_be_0_or_8_to_40 u_stop ();
    end
    if (BISS_ERROR_HIGH < 0 || BISS_ERROR_HIGH > 1) begin : g_bad_biss_error_high
      initial $display("ERROR: %m: parameter BISS_ERROR_HIGH = %0d must be 0 or 1",
                       BISS_ERROR_HIGH);
      prenc_board_parameter_BISS_ERROR_HIGH_must_be_0_or_1 u_stop ();
    end
    if (ABI < 0 || ABI > 1) begin : g_bad_abi
      initial $display("ERROR: %m: parameter ABI = %0d must be 0 or 1", ABI);
      prenc_board_parameter_ABI_must_be_0_or_1 u_stop ();
    end
    if (UVW < 0 || UVW > 1) begin : g_bad_uvw
      initial $display("ERROR: %m: parameter UVW = %0d must be 0 or 1", UVW);
      prenc_board_parameter_UVW_must_be_0_or_1 u_stop ();
    end
    if (ABI_EDGE_NS < 1 || ABI_EDGE_NS > 1000000) begin : g_bad_abi_edge
      initial $display("ERROR: %m: parameter ABI_EDGE_NS = %0d is out of range 1..1000000",
                       ABI_EDGE_NS);
      prenc_board_parameter_ABI_EDGE_NS_out_of_range_1_to_1000000 u_stop ();
    end
    if (BISS_TIMEOUT_US < 1 || BISS_TIMEOUT_US > 1000) begin : g_bad_biss_timeout
      initial $display("ERROR: %m: parameter BISS_TIMEOUT_US = %0d is out of range 1..1000",
                       BISS_TIMEOUT_US);
      prenc_board_parameter_BISS_TIMEOUT_US_out_of_range_1_to_1000 u_stop ();
    end
  endgenerate

  wire [N-1:0]  pos_abs;
  wire [N+1:0]  pos_hyb;
  wire          valid;
  wire [2:0]    mode_now;
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
  wire          clear_errors;

  // The warning before a failure: the corrections' rate, per head and the sync track.
  wire [2:0] warnings;
  wire       warning;

  generate
    if (HEALTH == 1) begin : g_health
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
    end else begin : g_no_health
      assign warnings = 3'b000;
      assign warning  = 1'b0;
      wire unused_health = &{1'b0, track1_error, track2_error};
    end
  endgenerate

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
    .resolution    (1'b1),
    .clear_errors  (clear_errors),
    .pos_abs       (pos_abs),
    .pos_hyb       (pos_hyb),
    .pos_valid     (valid),
    .mode          (mode_now),
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

  // Fine position and velocity (FINE_BITS is checked there), with FB >= F fraction bits:
  // the SPI's 14 (FB's floor at F bits is the floor at F bits). The velocity's window:
  // 34 us, 1024 clocks at 30 MHz.
  localparam integer F         = FINE_BITS;
  localparam integer SPI_F     = (SPI == 1 && FINE == 1 && N < 12) ? 12 - N : 0;
  localparam integer FB        = (SPI_F > F) ? SPI_F : F;
  localparam integer WINDOW    = CLK_HZ / 29297;
  localparam integer POS_BITS  = N + 2 + F;
  localparam integer FULL_BITS = N + 2 + FB;
  localparam integer ABI_MIN_GAP = (ABI_EDGE_NS * (CLK_HZ / 1000000) + 999) / 1000;
  localparam integer LOOKAHEAD = (EXTRAPOLATE == 1 && FINE == 1) ? 2 * (10 + FILTER + 4 * CAL)
                                                                : 0;
  wire [FULL_BITS-1:0] fine_full;
  wire [POS_BITS-1:0]  fine_pos = fine_full[FULL_BITS-1:FB-F];
  wire                 fine_valid;
  wire                 interpolated;
  wire [31:0]          velocity;        // quarters per clock x 2^32, signed
  wire                 velocity_valid;
  wire [31:0]          fine_word = {{(32 - POS_BITS){1'b0}}, fine_pos};

  wire         cal_write;
  wire [N+1:0] cal_address;
  wire [15:0]  cal_data;

  prenc_fine #(
    .N                (N),
    .FINE_BITS        (FB),
    .LOOKAHEAD_HALVES (LOOKAHEAD),
    .WINDOW           (WINDOW),
    .ENABLE           (FINE),
    .CAL              (CAL),
    .CAL_FILE         (CAL_FILE),
    .EDGE_TOLERANCE   (EDGE_TOLERANCE)
  ) u_fine (
    .clk            (clk),
    .rst            (rst),
    .pos_hyb        (pos_hyb),
    .pos_valid      (valid),
    .step           (sync_step),
    .step_cw        (direction),
    .illegal        (sync_illegal),
    .cal_write      (cal_write),
    .cal_address    (cal_address),
    .cal_data       (cal_data),
    .fine_pos       (fine_full),
    .fine_valid     (fine_valid),
    .interpolated   (interpolated),
    .velocity       (velocity),
    .velocity_valid (velocity_valid)
  );

  // The host link, and the edges' timing for a calibration run (its EDGES answer).
  generate
    if (HOST_LINK == 1) begin : g_host_link
      wire [1:0]   edge_run;
      wire         edge_valid;
      wire         edge_cw;
      wire [N+1:0] edge_first;
      wire [15:0]  edge_interval0;
      wire [15:0]  edge_interval1;
      wire [15:0]  edge_interval2;
      wire         edge_lost;
      wire         edge_take;
      wire [15:0]  link_errors;
      wire         snapshot;

      if (EDGE_CAPTURE == 1) begin : g_edge_capture
        prenc_edge_capture #(
          .N (N)
        ) u_edges (
          .clk       (clk),
          .rst       (rst),
          .step      (sync_step),
          .step_cw   (direction),
          .illegal   (sync_illegal),
          .pos_hyb   (pos_hyb),
          .pos_valid (valid),
          .take      (edge_take),
          .run       (edge_run),
          .run_valid (edge_valid),
          .run_cw    (edge_cw),
          .run_edge  (edge_first),
          .interval0 (edge_interval0),
          .interval1 (edge_interval1),
          .interval2 (edge_interval2),
          .lost      (edge_lost)
        );
      end else begin : g_no_edge_capture
        assign edge_run       = 2'd0;
        assign edge_valid     = 1'b0;
        assign edge_cw        = 1'b0;
        assign edge_first     = {(N + 2){1'b0}};
        assign edge_interval0 = 16'd0;
        assign edge_interval1 = 16'd0;
        assign edge_interval2 = 16'd0;
        assign edge_lost      = 1'b0;
        wire unused_edges = &{1'b0, edge_take};
      end

      prenc_host_link #(
        .N      (N),
        .CLK_HZ (CLK_HZ),
        .BAUD   (BAUD),
        .CAL    (CAL)
      ) u_link (
        .clk           (clk),
        .rst           (rst),
        .rx            (uart_rx),
        .tx            (uart_tx),
        .pos_abs       (pos_abs),
        .pos_hyb       (pos_hyb),
        .pos_valid     (valid),
        .mode          (mode_now),
        .direction     (direction),
        .warnings      (warnings),
        .incremental   (incremental),
        .track1_pos    (track1_pos),
        .track1_valid  (track1_valid),
        .track2_pos    (track2_pos),
        .track2_valid  (track2_valid),
        .track1_errors (track1_errors),
        .track2_errors (track2_errors),
        .sync_errors   (sync_errors),
        .fine_pos      (fine_word),
        .velocity      (velocity),
        .fine_info     ({2'b00, interpolated, velocity_valid, F[3:0]}),
        .edge_run       (edge_run),
        .edge_valid     (edge_valid),
        .edge_cw        (edge_cw),
        .edge_first     (edge_first),
        .edge_interval0 (edge_interval0),
        .edge_interval1 (edge_interval1),
        .edge_interval2 (edge_interval2),
        .edge_lost      (edge_lost),
        .edge_take      (edge_take),
        .cal_write      (cal_write),
        .cal_address    (cal_address),
        .cal_data       (cal_data),
        .clear_errors  (clear_errors),
        .link_errors   (link_errors),
        .snapshot      (snapshot)
      );

      wire unused_link = &{1'b0, link_errors, snapshot};
    end else begin : g_no_host_link
      assign uart_tx      = 1'b1;
      assign cal_write    = 1'b0;
      assign cal_address  = {(N + 2){1'b0}};
      assign cal_data     = 16'd0;
      assign clear_errors = 1'b0;
      wire unused_link = &{1'b0, uart_rx, pos_abs, incremental, track1_pos, track1_valid,
                           track2_pos, track2_valid, track1_errors, track2_errors,
                           sync_errors, fine_word, interpolated, velocity_valid,
                           velocity};
    end
  endgenerate

  // Multi-turn from the fine position and the incremental count (in the fine units);
  // `turns_full` is {turns, fine position} of the clock before, always one pair.
  localparam integer BISS_TURN_BITS = (BISS_MT_BITS > 0) ? BISS_MT_BITS : 1;
  wire [BISS_TURN_BITS-1:0]           turns;
  wire                                turns_placed;
  wire [BISS_TURN_BITS+FULL_BITS-1:0] turns_full;
  wire [FULL_BITS-1:0]                count_fine;

  generate
    if (FB > 0) begin : g_count_fraction
      assign count_fine = {incremental[N+1:0], {FB{1'b0}}};
    end else begin : g_count
      assign count_fine = incremental[N+1:0];
    end
  endgenerate

  prenc_turns #(
    .POS_BITS   (FULL_BITS),
    .TURN_BITS  (BISS_TURN_BITS)
  ) u_turns (
    .clk      (clk),
    .rst      (rst),
    .position (fine_full),
    .valid    (fine_valid),
    .count    (count_fine),
    .turns    (turns),
    .full     (turns_full),
    .placed   (turns_placed)
  );

  // The position SSI and BiSS-C send: the fine one (HYBRID = 1) or its slot (0).
  reg fine_valid_d;  // fine_valid of the clock before, with turns_full
  always @(posedge clk) fine_valid_d <= rst ? 1'b0 : fine_valid;
  wire [FULL_BITS-1:0] full_held = turns_full[FULL_BITS-1:0];
  wire [POS_BITS-1:0]  fine_held = full_held[FULL_BITS-1:FB-F];
  wire [N-1:0]         slot_held = full_held[FULL_BITS-1:FB+2];
  wire [BISS_TURN_BITS-1:0] turns_held = turns_full[BISS_TURN_BITS+FULL_BITS-1:FULL_BITS];

  localparam integer SSI_WIDTH = (SSI_HYBRID == 1) ? POS_BITS : N;
  wire [SSI_WIDTH-1:0] ssi_position;
  wire                 ssi_busy;

  generate
    if (SSI_HYBRID == 1) begin : g_ssi_hybrid
      assign ssi_position = fine_held;
    end else begin : g_ssi_abs
      assign ssi_position = slot_held;
    end
  endgenerate

  prenc_ssi #(
    .WIDTH     (SSI_WIDTH),
    .ERROR_BIT (1),
    .WARN_BIT  (SSI_WARNING),
    .MONOFLOP  (SSI_MONOFLOP_US * (CLK_HZ / 1000000))
  ) u_ssi (
    .clk      (clk),
    .rst      (rst),
    .position (ssi_position),
    .valid    (fine_valid_d),
    .warn     (warning),
    .gray     (ssi_gray),
    .ssi_clk  (ssi_clk),
    .ssi_data (ssi_data),
    .busy     (ssi_busy)
  );

  // BiSS-C: multi-turn and single-turn; with BISS_ST_BITS a single-turn field of that
  // width (a layout a master knows): the fine position's top bits, zeros below.
  localparam integer BISS_ST_NATURAL = (BISS_HYBRID == 1) ? POS_BITS : N;
  localparam integer BISS_ST         = (BISS_ST_BITS != 0) ? BISS_ST_BITS : BISS_ST_NATURAL;
  localparam integer BISS_BITS       = BISS_MT_BITS + BISS_ST;
  wire [BISS_ST-1:0]        biss_single;
  wire [BISS_BITS-1:0]      biss_data;
  wire                      biss_busy;
  wire                      biss_latch;

  generate
    if (BISS_ST_BITS == 0 && BISS_HYBRID == 1) begin : g_biss_st_hyb
      assign biss_single = fine_held;
    end else if (BISS_ST_BITS == 0) begin : g_biss_st_abs
      assign biss_single = slot_held;
    end else if (BISS_ST_BITS <= FULL_BITS) begin : g_biss_st_top
      assign biss_single = full_held[FULL_BITS-1:FULL_BITS-BISS_ST];
    end else begin : g_biss_st_padded
      assign biss_single = {full_held, {(BISS_ST - FULL_BITS){1'b0}}};
    end
    if (BISS_MT_BITS > 0) begin : g_biss_mt
      assign biss_data = {turns_held, biss_single};
    end else begin : g_biss_st
      assign biss_data = biss_single;
    end
  endgenerate

  prenc_biss #(
    .DATA_BITS (BISS_BITS),
    .TIMEOUT   (BISS_TIMEOUT_US * (CLK_HZ / 1000000))
  ) u_biss (
    .clk     (clk),
    .rst     (rst),
    .data    (biss_data),
    .error_n (BISS_ERROR_HIGH == 1 ? ~fine_valid_d : fine_valid_d),
    .warn_n  (~(warning | (mode_now == 3'd2) | (mode_now == 3'd3))),
    .ma      (biss_ma),
    .slo     (biss_slo),
    .busy    (biss_busy),
    .latch   (biss_latch)
  );

  // The position as the AS5047P's outputs give it: at least 14 bits (the fine
  // position, or below N = 12 without prenc_fine pos_hyb and zeros).
  // held_14 is prenc_turns' register (with SSI's and BiSS-C's position); next_14 the top
  // 14 bits of the value it takes on the next clock, for the SPI, which registers them.
  localparam integer SHAFT_BITS = (FULL_BITS >= 14) ? FULL_BITS : 14;
  wire [SHAFT_BITS-1:0] held_14;
  wire [13:0]           next_14;

  generate
    if (FULL_BITS >= 14) begin : g_held_14
      assign held_14 = full_held;
      assign next_14 = fine_full[FULL_BITS-1:FULL_BITS-14];
    end else begin : g_held_14_padded
      assign held_14 = {full_held, {(14 - FULL_BITS){1'b0}}};
      assign next_14 = {fine_full, {(14 - FULL_BITS){1'b0}}};
    end
  endgenerate

  // SPI, as the AS5047P: the top 14 bits. Its registers (the zero, DIR, ABI's and UVW's
  // settings) are SPI_ZERO, SPI_SETTINGS1 and SPI_SETTINGS2 without it.
  wire [13:0] spi_zero;
  wire [7:0]  spi_settings1;
  wire [7:0]  spi_settings2;

  generate
    if (SPI == 1) begin : g_spi
      prenc_as5047 #(
        .ZERO      (SPI_ZERO),
        .SETTINGS1 (SPI_SETTINGS1),
        .SETTINGS2 (SPI_SETTINGS2)
      ) u_spi (
        .clk       (clk),
        .rst       (rst),
        .angle     (next_14),
        .valid     (fine_valid),
        .warning   (warning),
        .csn       (spi_csn),
        .sclk      (spi_sclk),
        .mosi      (spi_mosi),
        .miso      (spi_miso),
        .miso_oe   (spi_miso_oe),
        .zero      (spi_zero),
        .settings1 (spi_settings1),
        .settings2 (spi_settings2)
      );
    end else begin : g_no_spi
      localparam [31:0] ZERO_32 = SPI_ZERO;
      localparam [31:0] S1_32   = SPI_SETTINGS1;
      localparam [31:0] S2_32   = SPI_SETTINGS2;
      assign spi_miso      = 1'b0;
      assign spi_miso_oe   = 1'b0;
      assign spi_zero      = ZERO_32[13:0];
      assign spi_settings1 = S1_32[7:0];
      assign spi_settings2 = S2_32[7:0];
      wire unused_spi = &{1'b0, spi_csn, spi_sclk, spi_mosi, next_14, warning};
    end
  endgenerate

  // ABI and UVW: the position turned by DIR and less the zero, registered.
  reg  [SHAFT_BITS-1:0] shaft;
  reg                   shaft_valid;
  wire [SHAFT_BITS-1:0] zero_shaft = {spi_zero, {(SHAFT_BITS - 14){1'b0}}};
  always @(posedge clk) begin
    shaft       <= (spi_settings1[2] ? ~held_14 : held_14) - zero_shaft;   // ~: floor of -held
    shaft_valid <= rst ? 1'b0 : fine_valid_d;
  end

  generate
    if (ABI == 1) begin : g_abi
      prenc_abi #(
        .B       (SHAFT_BITS),
        .STEPS   (ABI_STEPS),
        .MIN_GAP (ABI_MIN_GAP)
      ) u_abi (
        .clk       (clk),
        .rst       (rst),
        .position  (shaft),
        .valid     (shaft_valid),
        .settings1 (spi_settings1),
        .settings2 (spi_settings2),
        .a         (abi_a),
        .b         (abi_b),
        .i         (abi_i)
      );
    end else begin : g_no_abi
      assign abi_a = 1'b0;
      assign abi_b = 1'b0;
      assign abi_i = 1'b0;
    end
    if (UVW == 1) begin : g_uvw
      prenc_uvw #(
        .B          (SHAFT_BITS),
        .POLE_PAIRS (UVW_POLE_PAIRS)
      ) u_uvw (
        .clk       (clk),
        .rst       (rst),
        .position  (shaft),
        .valid     (shaft_valid),
        .settings2 (spi_settings2),
        .u         (uvw_u),
        .v         (uvw_v),
        .w         (uvw_w)
      );
    end else begin : g_no_uvw
      assign uvw_u = 1'b0;
      assign uvw_v = 1'b0;
      assign uvw_w = 1'b0;
    end
  endgenerate

  wire unused_shaft = &{1'b0, shaft, shaft_valid, spi_settings1, spi_settings2};

  assign led_valid       = valid;
  assign led_acquire     = (mode_now == 3'd0);
  assign led_normal      = (mode_now == 3'd1);
  assign led_reduced     = (mode_now == 3'd2) | (mode_now == 3'd3);
  assign led_incremental = (mode_now == 3'd4);
  assign pos_valid       = valid;
  assign mode            = mode_now;

  wire unused_ok = &{1'b0, position, ssi_busy, biss_busy, biss_latch,
                     turns_placed, turns, turns_held, slot_held, fine_held, full_held, velocity,
                     sync_step, sync_illegal, warnings};

endmodule

`resetall
