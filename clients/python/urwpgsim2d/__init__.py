"""A client of the URWPGSim2D server's strategy protocol (standard library only, Python >= 3.9).

Strategy and play() play a remote team (run --strategy TEAM=remote:PORT), play_series() every match of a
tournament's remote entrant (tournament --entrant NAME=remote:PORT) on one connection; FishEnv (urwpgsim2d.env)
drives one team in lockstep as a Gymnasium environment.
"""

from .client import Refused, Strategy, main, parse_address, play, play_series
from .drawing import Drawing
from .protocol import VERSION, Assignment, Ball, End, Fish, Obstacle, ProtocolError, Snapshot

__all__ = ["VERSION", "Assignment", "Ball", "Drawing", "End", "Fish", "Obstacle", "ProtocolError", "Refused", "Snapshot", "Strategy", "main", "parse_address", "play", "play_series"]
