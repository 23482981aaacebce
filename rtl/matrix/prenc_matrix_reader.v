// SPDX-License-Identifier: Apache-2.0
// prenc_matrix_reader: absolute position from one image of a matrix-code disc.
//
// A small image sensor (the paper's prototype: 15 x 15 pixels) streams a frame in
// raster order: row 0 first, x increasing with the code's position. The N tracks
// lie across the rows, track t covering rows TOP + t*CELL .. TOP + (t+1)*CELL - 1
// (the "band"); along x, a cell is CELL pixels, and WIDTH >= (N+1)*CELL pixels show
// N whole cells whatever the disc's angle. While the frame streams in, the reader
//   - keeps the darkest and brightest band pixel, and stores each track's centre
//     row (TOP + t*CELL + CELL/2);
//   - adds the step d(x) = |pixel(x) - pixel(x-1)| of every band row to the edge
//     energy of phase x mod CELL when it is a peak of its row (d(x) >= d(x-1) and
//     d(x) > d(x+1), 2 <= x <= WIDTH-2, so that an edge the image border cuts
//     cannot pull the phase with its tail): the phase with the most energy is
//     where cell boundaries fall.
// After the last pixel it picks the centre pixel of N whole cells on each track,
// from the first boundary phi on: x = phi + CELL/2 + i*CELL, i = 0..N-1, compares
// each with the threshold (darkest + brightest) / 2 (a light cell reads 1), forms
// the window (first column most significant, track 0 the MSB of a column), checks
// each column's parity (CHECKSUM = 1) and looks the position up in the table.
// The model is prenc.matrix.reader (the same integers).
//
// A reading is trusted (out_ok) only when the table is ready, the contrast
// (brightest - darkest) is at least MIN_CONTRAST, every sampled pixel is more than
// contrast/8 away from the threshold (else out_uncertain), and, with CHECKSUM = 1,
// every column has even parity (else out_checksum_error). The position of the
// image's left edge is out_position - out_phase/CELL cells.
//
// Timing: out_valid pulses on the N*N + 5th clock after the frame's last pixel.
// A frame whose first pixel comes while busy is ignored; a pixel_first in the middle
// of a frame starts a new frame (the partial one is dropped).
//
// Latency: out_valid pulses on the N*N + 5th clock after the frame's last pixel (the
// timing above).
//
// Parameters (checked; an illegal value stops elaboration with the name of the problem)
//   N 2..4, CHECKSUM 0..1, CELL 3..16, WIDTH (N+1)*CELL..64, HEIGHT TOP+N*CELL..255,
//   TOP 0..255, PIXEL_BITS 4..12, MIN_CONTRAST 1..2^PIXEL_BITS-1,
//   TABLE, TABLE_FILE as prenc_matrix_table.
//
// Ports
//   clk, rst        one clock; synchronous active-high reset
//   pixel_valid     pixel holds a pixel
//   pixel_first     with pixel_valid: this is pixel (0, 0) of a frame
//   pixel           intensity, PIXEL_BITS bits, larger is lighter
//   ready           the table can be read (after reset; see prenc_matrix_table)
//   busy            a frame is being converted
//   out_valid       one clock: the out_* ports hold a new reading
//   out_position    window position 0..2^A-1, A = N*(N-CHECKSUM)
//   out_phase       the first whole cell starts at pixel out_phase
//   out_cells       the N*N cells read, first column most significant
//   out_ok, out_low_contrast, out_uncertain, out_checksum_error  (above)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_matrix_reader #(
  parameter integer N            = 4,
  parameter integer CHECKSUM     = 0,
  parameter integer CELL         = 3,
  parameter integer WIDTH        = 15,
  parameter integer HEIGHT       = 15,
  parameter integer TOP          = 1,
  parameter integer PIXEL_BITS   = 8,
  parameter integer MIN_CONTRAST = 32,
  parameter [71:0]  TABLE        = "file",
  parameter         TABLE_FILE   = "prenc_matrix_n4.hex",
  // derived; do not override
  parameter integer A            = N * (N - CHECKSUM),
  parameter integer PHASE_BITS   = (CELL > 1) ? $clog2(CELL) : 1
) (
  input  wire                  clk,
  input  wire                  rst,
  input  wire                  pixel_valid,
  input  wire                  pixel_first,
  input  wire [PIXEL_BITS-1:0] pixel,
  output wire                  ready,
  output wire                  busy,
  output reg                   out_valid,
  output reg  [A-1:0]          out_position,
  output reg  [PHASE_BITS-1:0] out_phase,
  output reg  [N*N-1:0]        out_cells,
  output reg                   out_ok,
  output reg                   out_low_contrast,
  output reg                   out_uncertain,
  output reg                   out_checksum_error
);

  localparam integer PB = PIXEL_BITS;
  localparam integer EW = PB + 12;             // edge energy: <= 64 rows x 64 pairs
  localparam integer BAND_END = TOP + N * CELL;

  generate
    if (N < 2 || N > 4) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..4", N);
      prenc_matrix_reader_parameter_N_out_of_range_2_to_4 u_stop ();
    end
    if (CHECKSUM < 0 || CHECKSUM > 1) begin : g_bad_checksum
      initial $display("ERROR: %m: parameter CHECKSUM = %0d is not 0 or 1", CHECKSUM);
      prenc_matrix_reader_parameter_CHECKSUM_not_0_or_1 u_stop ();
    end
    if (CELL < 3 || CELL > 16) begin : g_bad_cell
      initial $display("ERROR: %m: parameter CELL = %0d is out of range 3..16", CELL);
      prenc_matrix_reader_parameter_CELL_out_of_range_3_to_16 u_stop ();
    end
    if (WIDTH < (N + 1) * CELL || WIDTH > 64) begin : g_bad_width
      initial $display("ERROR: %m: parameter WIDTH = %0d is out of range (N+1)*CELL = %0d..64",
                       WIDTH, (N + 1) * CELL);
      prenc_matrix_reader_parameter_WIDTH_out_of_range u_stop ();
    end
    if (TOP < 0 || TOP > 255) begin : g_bad_top
      initial $display("ERROR: %m: parameter TOP = %0d is out of range 0..255", TOP);
      prenc_matrix_reader_parameter_TOP_out_of_range_0_to_255 u_stop ();
    end
    if (HEIGHT < BAND_END || HEIGHT > 255) begin : g_bad_height
      initial $display("ERROR: %m: parameter HEIGHT = %0d is out of range TOP+N*CELL = %0d..255",
                       HEIGHT, BAND_END);
      prenc_matrix_reader_parameter_HEIGHT_out_of_range u_stop ();
    end
    if (PIXEL_BITS < 4 || PIXEL_BITS > 12) begin : g_bad_pixel_bits
      initial $display("ERROR: %m: parameter PIXEL_BITS = %0d is out of range 4..12", PIXEL_BITS);
      prenc_matrix_reader_parameter_PIXEL_BITS_out_of_range_4_to_12 u_stop ();
    end
    if (MIN_CONTRAST < 1 || MIN_CONTRAST >= (1 << PIXEL_BITS)) begin : g_bad_min_contrast
      initial $display("ERROR: %m: parameter MIN_CONTRAST = %0d is out of range 1..%0d",
                       MIN_CONTRAST, (1 << PIXEL_BITS) - 1);
      prenc_matrix_reader_parameter_MIN_CONTRAST_out_of_range u_stop ();
    end
  endgenerate

  // ---- Capture: coordinates, statistics, edge energy, centre rows ----------------
  localparam [31:0] LAST_X    = WIDTH - 1;
  localparam [31:0] LAST_Y    = HEIGHT - 1;
  localparam [31:0] LAST_MOD  = CELL - 1;
  localparam [31:0] MIN_C     = MIN_CONTRAST;
  localparam [31:0] HALF_CELL = CELL / 2;
  localparam [31:0] TOP_ROW   = TOP;
  localparam [31:0] BAND_END_ROW = BAND_END;
  localparam [31:0] LAST_INDEX = N - 1;

  // A row at or below a row (a function: with TOP = 0 the band's first row is 0, which
  // every row is at or below, and lint would flag the comparison as constant).
  function at_or_below(input [7:0] row, input [7:0] first);
    at_or_below = (row >= first);
  endfunction

  reg  [7:0]          x_reg;                   // coordinates of the next pixel
  reg  [7:0]          y_reg;
  reg  [PHASE_BITS-1:0] xmod_reg;              // x mod CELL of the next pixel
  reg                 in_frame_reg;
  reg  [PB-1:0]       prev_reg;                // the pixel left of the next one
  reg  [PB-1:0]       step1_reg;               // d(x-1) and d(x-2) of the next pixel x
  reg  [PB-1:0]       step2_reg;
  reg  [PHASE_BITS-1:0] prev_mod_reg;          // (x-1) mod CELL of the next pixel x
  reg  [PB-1:0]       darkest_reg;
  reg  [PB-1:0]       brightest_reg;
  reg  [CELL*EW-1:0]  energy_reg;              // edge energy of each phase
  reg                 frame_done_reg;          // the last pixel came on the last clock

  wire                take = pixel_valid && (pixel_first ? !busy : in_frame_reg);
  wire [7:0]          cx = pixel_first ? 8'd0 : x_reg;
  wire [7:0]          cy = pixel_first ? 8'd0 : y_reg;
  wire [PHASE_BITS-1:0] cmod = pixel_first ? {PHASE_BITS{1'b0}} : xmod_reg;
  wire                in_band = at_or_below(cy, TOP_ROW[7:0]) && cy < BAND_END_ROW[7:0];
  wire                row_end = cx == LAST_X[7:0];
  wire [PB-1:0]       diff = pixel > prev_reg ? pixel - prev_reg : prev_reg - pixel;

  // The centre-row store: track t's centre row goes to words t*64 + x.
  reg  [PB-1:0]       rows [0:255];
  reg                 store;
  reg  [1:0]          store_track;
  reg  [31:0]         centre_row;
  integer             t;

  always @* begin
    store       = 1'b0;
    store_track = 2'd0;
    centre_row  = 32'd0;
    for (t = 0; t < N; t = t + 1) begin
      centre_row = TOP + t * CELL + CELL / 2;
      if ({24'd0, cy} == centre_row) begin
        store       = 1'b1;
        store_track = t[1:0];
      end
    end
  end

  always @(posedge clk) begin
    frame_done_reg <= 1'b0;
    if (take) begin
      prev_reg     <= pixel;
      step1_reg    <= diff;
      step2_reg    <= step1_reg;
      prev_mod_reg <= cmod;
      if (row_end) begin
        x_reg    <= 8'd0;
        y_reg    <= cy + 8'd1;
        xmod_reg <= {PHASE_BITS{1'b0}};
      end else begin
        x_reg    <= cx + 8'd1;
        y_reg    <= cy;
        xmod_reg <= (cmod == LAST_MOD[PHASE_BITS-1:0]) ? {PHASE_BITS{1'b0}}
                                                       : cmod + 1'b1;
      end
      in_frame_reg <= !(row_end && cy == LAST_Y[7:0]);
      frame_done_reg <= row_end && cy == LAST_Y[7:0];
      if (pixel_first) begin
        darkest_reg   <= {PB{1'b1}};
        brightest_reg <= {PB{1'b0}};
        energy_reg    <= {(CELL*EW){1'b0}};
      end
      if (in_band) begin
        if (pixel < (pixel_first ? {PB{1'b1}} : darkest_reg)) begin
          darkest_reg <= pixel;
        end
        if (pixel > (pixel_first ? {PB{1'b0}} : brightest_reg)) begin
          brightest_reg <= pixel;
        end
        // d(x-1) is complete now: count it if it is a peak (x-1 >= 2)
        if (cx >= 8'd3 && step1_reg >= step2_reg && step1_reg > diff) begin
          energy_reg[prev_mod_reg*EW +: EW] <= energy_reg[prev_mod_reg*EW +: EW] +
                                               {{(EW-PB){1'b0}}, step1_reg};
        end
      end
    end
    if (rst) begin
      in_frame_reg   <= 1'b0;
      frame_done_reg <= 1'b0;
      x_reg          <= 8'd0;
      y_reg          <= 8'd0;
      xmod_reg       <= {PHASE_BITS{1'b0}};
    end
  end

  always @(posedge clk) begin
    if (take && store) begin
      rows[{store_track, cx[5:0]}] <= pixel;
    end
  end

  // ---- Conversion: phase, N*N samples, table lookup ------------------------------
  localparam [2:0] S_IDLE   = 3'd0;
  localparam [2:0] S_PHASE  = 3'd1;
  localparam [2:0] S_SAMPLE = 3'd2;
  localparam [2:0] S_LOOKUP = 3'd3;
  localparam [2:0] S_OUT    = 3'd4;

  reg  [2:0]            state_reg;
  reg  [PHASE_BITS-1:0] phase_reg;
  reg  [PB-1:0]         threshold_reg;
  reg  [PB-1:0]         margin_reg;
  reg                   low_contrast_reg;
  reg  [1:0]            track_reg;             // sample being addressed
  reg  [1:0]            column_reg;
  reg  [5:0]            sample_x_reg;          // x of column column_reg's centre
  reg                   sample_pending_reg;    // rows_q holds a sample to use
  reg                   sample_last_reg;       // ... and it is the last one
  reg  [PB-1:0]         rows_q;
  reg  [N*N-1:0]        cells_reg;
  reg                   uncertain_reg;
  reg                   table_rd;

  // argmax of the edge energy, the first phase on a tie
  reg  [PHASE_BITS-1:0] best_phase;
  reg  [EW-1:0]         best_energy;
  integer               c;
  always @* begin
    best_phase  = {PHASE_BITS{1'b0}};
    best_energy = energy_reg[EW-1:0];
    for (c = 1; c < CELL; c = c + 1) begin
      if (energy_reg[c*EW +: EW] > best_energy) begin
        best_phase  = c[PHASE_BITS-1:0];
        best_energy = energy_reg[c*EW +: EW];
      end
    end
  end

  wire [PB-1:0] contrast = brightest_reg - darkest_reg;
  wire          sample_bit = rows_q > threshold_reg;
  wire [PB-1:0] sample_distance = sample_bit ? rows_q - threshold_reg : threshold_reg - rows_q;

  // parity of each column of the cells read; the table address without parity bits
  reg           parity_error;
  reg [A-1:0]   table_addr;
  integer       i;
  always @* begin
    parity_error = 1'b0;
    table_addr   = {A{1'b0}};
    for (i = 0; i < N; i = i + 1) begin
      if (CHECKSUM != 0) begin
        parity_error = parity_error | (^cells_reg[(N-1-i)*N +: N]);
        table_addr = (table_addr << (N - 1)) | {{(A-N+1){1'b0}}, cells_reg[(N-1-i)*N + 1 +: N-1]};
      end else begin
        table_addr = (table_addr << N) | {{(A-N){1'b0}}, cells_reg[(N-1-i)*N +: N]};
      end
    end
  end

  wire [A-1:0] table_data;

  prenc_matrix_table #(
    .N          (N),
    .CHECKSUM   (CHECKSUM),
    .TABLE      (TABLE),
    .TABLE_FILE (TABLE_FILE)
  ) u_table (
    .clk     (clk),
    .rst     (rst),
    .ready   (ready),
    .rd_en   (table_rd),
    .rd_addr (table_addr),
    .rd_data (table_data)
  );

  always @(posedge clk) begin
    rows_q <= rows[{track_reg, sample_x_reg}];
  end

  assign busy = frame_done_reg || state_reg != S_IDLE;

  always @(posedge clk) begin
    out_valid <= 1'b0;
    table_rd  <= 1'b0;
    case (state_reg)
      S_IDLE: begin
        if (frame_done_reg) begin
          state_reg <= S_PHASE;
        end
      end
      S_PHASE: begin
        phase_reg          <= best_phase;
        threshold_reg      <= darkest_reg + {1'b0, contrast[PB-1:1]};  // (dark + bright) / 2
        margin_reg         <= {3'b000, contrast[PB-1:3]};
        low_contrast_reg   <= contrast < MIN_C[PB-1:0];
        track_reg          <= 2'd0;
        column_reg         <= 2'd0;
        sample_x_reg       <= {{(6-PHASE_BITS){1'b0}}, best_phase} + HALF_CELL[5:0];
        sample_pending_reg <= 1'b0;
        sample_last_reg    <= 1'b0;
        uncertain_reg      <= 1'b0;
        state_reg          <= S_SAMPLE;
      end
      S_SAMPLE: begin
        // address the next sample; use the one read on the clock before
        sample_pending_reg <= !sample_last_reg;
        if (track_reg == LAST_INDEX[1:0]) begin
          track_reg    <= 2'd0;
          column_reg   <= column_reg + 2'd1;
          sample_x_reg <= sample_x_reg + CELL[5:0];
          sample_last_reg <= column_reg == LAST_INDEX[1:0];
        end else begin
          track_reg <= track_reg + 2'd1;
        end
        if (sample_pending_reg) begin
          cells_reg     <= {cells_reg[N*N-2:0], sample_bit};
          uncertain_reg <= uncertain_reg | (sample_distance <= margin_reg);
          if (sample_last_reg) begin
            table_rd  <= 1'b1;
            state_reg <= S_LOOKUP;
          end
        end
      end
      S_LOOKUP: begin
        state_reg <= S_OUT;
      end
      default: begin // S_OUT
        out_valid          <= 1'b1;
        out_position       <= table_data;
        out_phase          <= phase_reg;
        out_cells          <= cells_reg;
        out_low_contrast   <= low_contrast_reg;
        out_uncertain      <= uncertain_reg;
        out_checksum_error <= CHECKSUM != 0 && parity_error;
        out_ok             <= ready && !low_contrast_reg && !uncertain_reg &&
                              !(CHECKSUM != 0 && parity_error);
        state_reg          <= S_IDLE;
      end
    endcase
    if (rst) begin
      state_reg <= S_IDLE;
      out_valid <= 1'b0;
      table_rd  <= 1'b0;
    end
  end

endmodule

`resetall
