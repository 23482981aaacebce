// prenc_track_monitor: how far one track's readings confirm the code word, and its
// error count.
//
// Each check of the track (one head reading at a strobe, against the predicted bit)
// is made at a slot of the reader's incremental slot count. The monitor keeps the
// interval [lo, hi] of consecutive slots at which every reading of this track has
// agreed since its last disagreement (or since `clear`). Re-reading a slot in_run
// the interval (a reversal, jitter at mid-slot) does not lengthen it; only a new
// neighbouring slot does. A disagreement empties it.
//
// Why an interval of N slots is a proof: N consecutive track bits are a code word,
// and on a de Bruijn disc each code word appears once. If N consecutive readings
// all agree with the position the reader holds, that position is the only one
// these readings allow, unless one of them was itself a misread. With RUN_LONG
// (at least 2N) consecutive agreeing slots, one misread cannot fake it either:
// the slots on one side of it are still N consecutive correct readings.
//
// Readings that formed the word prove nothing about it: re-read (after a reversal)
// they agree with the word even where they are wrong, as a spot on the track is
// wrong every time. So while the word is being formed, the monitor keeps the hull
// of the slots at which this track's head fed it (`fill`, restarted when the word
// is empty), and later checks at those slots neither lengthen nor start the
// interval (a disagreement there still empties it).
//
// The `*_next` outputs show the state this clock's check leads to (combinational),
// so that the mode state machine decides on the same clock as the check.
//
// Parameters
//   N            code word length, 2..24 (slots count modulo 2^N)
//   RUN_LONG     agreeing slots for the single-track proof, 2N..2^N; default 4N,
//                or 2^N when that is less
//   ERROR_WIDTH  disagreement counter width, 1..32 (saturates)
//
// Ports
//   clear          empty the interval (word not full, illegal quadrature step)
//   fill           this track's head feeds the word on this clock (strobe while
//                  the word is not full, in the direction where this head leads)
//   word_empty     the word holds no bit (a fill then starts a new hull)
//   check          a reading of this track is checked on this clock
//   mismatch       it disagreed with the prediction
//   slot           the incremental slot count at the strobe
//   clear_errors   zero the error counter
//   run_n_next     the interval will span at least N slots
//   run_2n_next    the interval will span at least 2N slots
//   run_long_next  the interval will span at least RUN_LONG slots
//   run_n          run_n_next, registered
//   errors         disagreements counted since reset or clear_errors

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_track_monitor #(
  parameter integer N           = 10,
  parameter integer RUN_LONG    = (4 * N < (1 << N)) ? 4 * N : (1 << N),
  parameter integer ERROR_WIDTH = 16
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire                   clear,
  input  wire                   fill,
  input  wire                   word_empty,
  input  wire                   check,
  input  wire                   mismatch,
  input  wire [N-1:0]           slot,
  input  wire                   clear_errors,
  output wire                   run_n_next,
  output wire                   run_2n_next,
  output wire                   run_long_next,
  output wire                   run_n,
  output wire [ERROR_WIDTH-1:0] errors
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_track_monitor_parameter_N_out_of_range_2_to_24 u_stop ();
    end else if (RUN_LONG < 2 * N || RUN_LONG > (1 << N)) begin : g_bad_run_long
      initial $display("ERROR: %m: parameter RUN_LONG = %0d is out of range 2N..2^N", RUN_LONG);
      prenc_track_monitor_parameter_RUN_LONG_out_of_range_2N_to_2_pow_N u_stop ();
    end
    if (ERROR_WIDTH < 1 || ERROR_WIDTH > 32) begin : g_bad_error_width
      initial $display("ERROR: %m: parameter ERROR_WIDTH = %0d is out of range 1..32", ERROR_WIDTH);
      prenc_track_monitor_parameter_ERROR_WIDTH_out_of_range_1_to_32 u_stop ();
    end
  endgenerate

  localparam [31:0] SPAN_N_32    = N - 1;         // hi - lo for an interval of N slots
  localparam [31:0] SPAN_LONG_32 = RUN_LONG - 1;  // hi - lo for RUN_LONG slots
  localparam [31:0] SPAN_2N_32   = (2 * N < (1 << N) ? 2 * N : (1 << N)) - 1;
  localparam [N:0]  SPAN_N       = SPAN_N_32[N:0];
  localparam [N:0]  SPAN_2N      = SPAN_2N_32[N:0];
  localparam [N:0]  SPAN_LONG    = SPAN_LONG_32[N:0];

  reg [N-1:0]           lo_reg;
  reg [N-1:0]           hi_reg;
  reg                   nonempty_reg;
  reg                   run_n_reg;
  reg [ERROR_WIDTH-1:0] errors_reg;

  wire [N-1:0] width  = hi_reg - lo_reg;
  wire [N-1:0] offset = slot - lo_reg;
  wire         in_run = nonempty_reg & (offset <= width);

  // Hull of the slots where this head fed the word.
  reg [N-1:0] fed_lo_reg;
  reg [N-1:0] fed_hi_reg;
  reg         fed_reg;

  wire [N-1:0] fed_width  = fed_hi_reg - fed_lo_reg;
  wire [N-1:0] fed_offset = slot - fed_lo_reg;
  wire         in_fed     = fed_reg & (fed_offset <= fed_width);
  wire [N-1:0] below      = fed_lo_reg - slot;  // distance below the hull
  wire [N-1:0] above      = slot - fed_hi_reg;  // distance above the hull

  always @(posedge clk) begin
    if (fill) begin
      if (word_empty || !fed_reg) begin
        fed_lo_reg <= slot;
        fed_hi_reg <= slot;
        fed_reg    <= 1'b1;
      end else if (!in_fed && below < above) begin
        fed_lo_reg <= slot;
      end else if (!in_fed) begin
        fed_hi_reg <= slot;
      end
    end
    if (rst) begin
      fed_reg <= 1'b0;
    end
  end

  // Next interval. Its width can only stay, grow by one slot, or restart at one
  // slot, so the run flags are chosen from comparisons of the registered width
  // (computed in parallel with the slot comparisons, not after them): the flags'
  // path is one comparison and a multiplexer, which is what the core's Fmax needs.
  reg [N-1:0] lo_next;
  reg [N-1:0] hi_next;
  reg         nonempty_next;
  reg         grow;     // the width grows by one
  reg         restart;  // the interval restarts at one slot

  wire extends_hi = (slot == hi_reg + 1'b1);
  wire extends_lo = (slot == lo_reg - 1'b1);

  always @* begin
    lo_next       = lo_reg;
    hi_next       = hi_reg;
    nonempty_next = nonempty_reg;
    grow          = 1'b0;
    restart       = 1'b0;
    if (check && mismatch) begin
      nonempty_next = 1'b0;
    end else if (check && in_fed) begin
      nonempty_next = nonempty_reg;  // a reading that formed the word: no evidence
    end else if (check) begin
      if (!nonempty_reg) begin
        lo_next       = slot;
        hi_next       = slot;
        nonempty_next = 1'b1;
        restart       = 1'b1;
      end else if (in_run) begin
        nonempty_next = 1'b1;
      end else if (extends_hi) begin
        hi_next = slot;
        grow    = 1'b1;
      end else if (extends_lo) begin
        lo_next = slot;
        grow    = 1'b1;
      end else begin
        lo_next = slot;
        hi_next = slot;
        restart = 1'b1;
      end
    end
    if (clear) begin
      nonempty_next = 1'b0;
    end
  end

  // width >= SPAN, and width + 1 >= SPAN (the width never reaches 2^N - 1 and grows:
  // a full circle is always in_run). A restarted interval has width 0 < every span.
  wire [N:0] width_ext = {1'b0, width};
  wire       keep_n    = (width_ext >= SPAN_N);
  wire       keep_2n   = (width_ext >= SPAN_2N);
  wire       keep_long = (width_ext >= SPAN_LONG);
  wire       grow_n    = (width_ext + 1'b1 >= SPAN_N);
  wire       grow_2n   = (width_ext + 1'b1 >= SPAN_2N);
  wire       grow_long = (width_ext + 1'b1 >= SPAN_LONG);

  assign run_n_next    = nonempty_next & ~restart & (grow ? grow_n : keep_n);
  assign run_2n_next   = nonempty_next & ~restart & (grow ? grow_2n : keep_2n);
  assign run_long_next = nonempty_next & ~restart & (grow ? grow_long : keep_long);

  always @(posedge clk) begin
    lo_reg       <= lo_next;
    hi_reg       <= hi_next;
    nonempty_reg <= nonempty_next;
    run_n_reg    <= run_n_next;
    if (check && mismatch && errors_reg != {ERROR_WIDTH{1'b1}}) begin
      errors_reg <= errors_reg + 1'b1;
    end
    if (clear_errors) begin
      errors_reg <= {ERROR_WIDTH{1'b0}};
    end
    if (rst) begin
      nonempty_reg <= 1'b0;
      run_n_reg    <= 1'b0;
      errors_reg   <= {ERROR_WIDTH{1'b0}};
    end
  end

  assign run_n  = run_n_reg;
  assign errors = errors_reg;

endmodule

`resetall
