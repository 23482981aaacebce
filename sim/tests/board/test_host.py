# SPDX-License-Identifier: Apache-2.0
"""prenc host: the user's errors, one line each, and CRC errors that never stop it.

The board here is a small Python responder on a real pseudo-terminal (the RTL
board is tested end to end in tb/board/prenc_board); it lets the test choose what a
board cannot be made to do: speak another protocol version, say nothing, or
corrupt an answer.
"""

from __future__ import annotations

import os
import threading
import tty

import pytest

from prenc.board import protocol
from prenc.cli.main import main
from prenc.board.protocol import Answer, FrameParser, Kind


class FakeBoard:
    def __init__(self, version: int = protocol.VERSION, silent: bool = False, corrupt_first: bool = False):
        self.master, self.slave = os.openpty()
        tty.setraw(self.master)
        self.port = os.ttyname(self.slave)
        self.version, self.silent, self.corrupt_first = version, silent, corrupt_first
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _answer(self, kind: Kind, seq: int) -> bytes:
        # FINE: a quarter of a turn and 1/64 of a quarter, at 600 rpm (N = 10, 30 MHz).
        velocity = round(600 / 60 * 4096 / 30e6 * 2**32)
        values = {Kind.ABS: {"position": 256}, Kind.STATUS: {"version": self.version, "bits": 10, "track1_errors": 0,
                                                            "track2_errors": 0, "sync_errors": 0, "link_errors": 0},
                  Kind.FINE: {"fine_position": (1024 << 6) + 1, "fine_bits": 6, "velocity": velocity,
                              "velocity_valid": True, "interpolated": True, "clk_mhz": 30}}
        return protocol.encode_answer(Answer(kind, True, 1, 1, False, seq, 1000 * seq, values[kind]))

    def _serve(self) -> None:
        parser, seq = FrameParser(max_len=protocol.REQUEST_MAX_LEN), 0
        import select

        while not self.stop.is_set():
            ready, _, _ = select.select([self.master], [], [], 0.05)
            if not ready:
                continue
            for frame in parser.feed(os.read(self.master, 64)):
                if self.silent:
                    continue
                out = self._answer(Kind(frame.payload[0]), seq)
                if self.corrupt_first and seq == 0:
                    os.write(self.master, out[:-1] + bytes([out[-1] ^ 1]))  # a bad CRC ...
                    out = self._answer(Kind(frame.payload[0]), seq)          # ... then the good one
                os.write(self.master, out)
                seq += 1

    def close(self) -> None:
        self.stop.set()
        self.thread.join()
        os.close(self.slave)
        os.close(self.master)


@pytest.fixture
def board(request):
    fake = FakeBoard(**getattr(request, "param", {}))
    yield fake
    fake.close()


def test_read_prints_the_answer(board, capsys):
    assert main(["host", "read", "--port", board.port, "--kind", "abs"]) == 0
    assert capsys.readouterr().out.startswith("abs 256 / 1024 = 90.000 deg  valid NORMAL cw")


def test_read_fine_prints_the_angle_and_the_rpm(board, capsys):
    assert main(["host", "read", "--port", board.port, "--kind", "fine"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"fine {(1024 << 6) + 1} / {1 << 18} = {360 * ((1024 << 6) + 1) / (1 << 18):.4f} deg"), out
    assert "+600.000 rpm" in out, out


def test_a_missing_port_is_one_line(capsys):
    assert main(["host", "read", "--port", "/dev/ttyNOSUCH0"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "port /dev/ttyNOSUCH0 not found" in err


@pytest.mark.parametrize("board", [{"silent": True}], indirect=True)
def test_no_answer_is_a_timeout(board, capsys):
    assert main(["host", "read", "--port", board.port, "--timeout", "0.3"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no answer from" in err and "within 0.3 s" in err


@pytest.mark.parametrize("board", [{"version": 9}], indirect=True)
def test_a_version_mismatch_is_named(board, capsys):
    assert main(["host", "read", "--port", board.port]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "protocol version mismatch: the board speaks version 9" in err


@pytest.mark.parametrize("board", [{"corrupt_first": True}], indirect=True)
def test_a_crc_error_is_counted_not_fatal(board, capsys):
    assert main(["host", "read", "--port", board.port, "--kind", "abs", "--json"]) == 0
    out = capsys.readouterr().out
    assert '"position": 256' in out and '"crc_errors": 1' in out


def test_plot_rejects_a_file_that_is_not_a_log(tmp_path, capsys):
    bad = tmp_path / "x.csv"
    bad.write_text("a,b\n1,2\n")
    assert main(["host", "plot", str(bad)]) == 1
    assert "not a `prenc host log` file" in capsys.readouterr().err


def test_calibrate_refuses_a_table_for_another_disc(board, tmp_path, capsys):
    from prenc.cal.table import Table

    table = Table.zero(6).write(tmp_path / "n6.cal")
    assert main(["calibrate", "--port", board.port, "--load", str(table)]) == 1
    err = capsys.readouterr().err
    assert err.startswith("prenc calibrate: error: calibration table") and "N = 6, the reader has N = 10" in err


def test_the_correction_map_places_each_heads_corrections_where_it_reads():
    """Head 1's corrections at the slot between two answers' positions, head 2's half a
    turn further; an interval without a valid position at both ends is not placed."""
    from prenc.board.host import CorrectionMap

    def health(position, t1, t2, sync, valid=True):
        return Answer(Kind.HEALTH, valid, 1, 1, True, 0, 0, {"position": position, "track1_errors": t1,
                                                            "track2_errors": t2, "sync_errors": sync,
                                                            "warnings": 0})

    m = CorrectionMap(bits=10, regions=32)
    m.add(health(100, 0, 0, 0))
    m.add(health(110, 2, 1, 0))        # middle slot 105: region 3; head 2 at 617: region 19
    m.add(health(1020, 2, 1, 1))       # backwards across the zero? no: the shorter way is -114
    m.add(health(1020, 5, 1, 1, valid=False))
    m.add(health(30, 6, 1, 1))         # from an invalid answer: not placed
    m.add(health(40, 7, 1, 1))         # 35: region 1
    rows = m.rows()
    assert rows[3]["head1"] == 2 and rows[19]["head2"] == 1 and rows[1]["head1"] == 1
    # 110 -> 1020 the shorter way round is 110 -> -4 (1020): the middle is 53, region 1.
    assert rows[1]["sync"] == 1
    assert sum(r["head1"] for r in rows) == 3 and m.skipped == 4
    assert "head 1" in m.table().splitlines()[0]
