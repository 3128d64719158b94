"""The strategy protocol (docs/protocol.md): JSON Lines over a TCP connection, and the messages as Python objects."""

import json
import socket
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

VERSION = 1
"""The protocol version this client speaks."""

MAX_LINE = 64 * 1024 * 1024
"""Longest line read from the server, bytes."""


class ProtocolError(Exception):
    """The server broke the protocol, or closed the connection before the end."""


@dataclass
class Obstacle:
    index: int
    kind: str
    center: Tuple[float, float]
    length: float
    width: float
    heading: float
    radius: float


@dataclass
class Assignment:
    """What the server tells a client once, after its hello."""

    version: int
    team: int
    item: str
    item_name: str
    fish: List[int]
    fish_count: int
    ball_count: int
    total_cycles: int
    cycle_ms: int
    deadline_ms: int
    field_length: float
    field_width: float
    obstacles: List[Obstacle]
    draw: bool = False
    """Whether the server records debug drawings (run --debug-draw)."""
    log: bool = False
    """Whether the server records what the strategy prints (run --strategy-log)."""
    series: bool = False
    """Whether the server keeps the connection after this match's end for a next one (a client that asked for it)."""

    @staticmethod
    def from_json(m: dict) -> "Assignment":
        f = m["field"]
        return Assignment(
            int(m["version"]), int(m["team"]), m.get("item", ""), m.get("itemName", ""), [int(i) for i in m["fish"]],
            int(m["fishCount"]), int(m["ballCount"]), int(m["totalCycles"]), int(m.get("cycleMs", 100)), int(m["deadlineMs"]),
            _num(f["length"]), _num(f["width"]),
            [Obstacle(int(o["index"]), o["kind"], _pair(o["center"]), _num(o["length"]), _num(o["width"]), _num(o["heading"]), _num(o["radius"]))
             for o in m.get("obstacles", [])],
            m.get("draw") is True, m.get("log") is True, m.get("series") is True)


@dataclass
class Fish:
    index: int
    team: int
    position: Tuple[float, float]
    heading: float
    speed: float
    angular_speed: float
    body_length: float
    head_length: float
    width: float
    joints: List[float]
    tail_lengths: List[float]
    decision: Tuple[int, int]


@dataclass
class Ball:
    index: int
    position: Tuple[float, float]
    velocity: Tuple[float, float]
    radius: float


def goals_of(m: dict) -> Tuple[int, ...]:
    """The `goals` of a cycle or end message: each team's score."""
    return tuple(int(g) for g in m["goals"])


@dataclass
class Snapshot:
    """What a strategy sees in one cycle (the SDK's MatchSnapshot)."""

    cycle: int
    goals: Tuple[int, ...]  # each team's score: 2 entries, or 4 in a four-team item
    sides_swapped: bool
    variables: Dict[str, str]
    fish: List[Fish]
    balls: List[Ball]
    assignment: Assignment = field(repr=False)

    @property
    def time(self) -> float:
        """The cycle's time, seconds."""
        return self.cycle * self.assignment.cycle_ms / 1000.0

    @property
    def my_fish(self) -> List[Fish]:
        """The fish this client decides for, in the order of its decisions."""
        return [self.fish[i] for i in self.assignment.fish]

    @staticmethod
    def from_json(m: dict, assignment: Assignment) -> "Snapshot":
        return Snapshot(
            int(m["cycle"]), goals_of(m), bool(m.get("sidesSwapped", False)),
            {str(k): str(v) for k, v in m.get("variables", {}).items()},
            [Fish(int(f["index"]), int(f["team"]), _pair(f["position"]), _num(f["heading"]), _num(f["speed"]), _num(f["angularSpeed"]),
                  _num(f["bodyLength"]), _num(f["headLength"]), _num(f["width"]), [_num(j) for j in f["joints"]],
                  [_num(t) for t in f["tailLengths"]], (int(f["decision"][0]), int(f["decision"][1]))) for f in m["fish"]],
            [Ball(int(b["index"]), _pair(b["position"]), _pair(b["velocity"]), _num(b["radius"])) for b in m["balls"]],
            assignment)


@dataclass
class End:
    """The server's last message: cycles played, the score, the faults charged to this client's team."""

    cycle: int
    goals: Tuple[int, ...]  # each team's score: 2 entries, or 4 in a four-team item
    faults: int


class Connection:
    """One TCP connection to the server, one JSON object per line each way."""

    def __init__(self, host: str, port: int, timeout: Optional[float] = None):
        self._socket = socket.create_connection((host, port), timeout=timeout)
        self._socket.settimeout(None)
        self._socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._reader = self._socket.makefile("rb")

    def send(self, message: dict) -> None:
        self._socket.sendall(json.dumps(message, separators=(",", ":"), ensure_ascii=False).encode("utf-8") + b"\n")

    def receive(self) -> Optional[dict]:
        """The next message, or None when the server has closed the connection."""
        line = self._reader.readline(MAX_LINE + 1)
        if not line:
            return None
        if len(line) > MAX_LINE:
            raise ProtocolError("a line from the server is longer than %d bytes" % MAX_LINE)
        try:
            message = json.loads(line)
        except ValueError as e:
            raise ProtocolError("the server sent a line that is not JSON: %s" % e) from None
        if not isinstance(message, dict) or not isinstance(message.get("type"), str):
            raise ProtocolError("the server sent a message without a type")
        return message

    def close(self) -> None:
        try:
            self._reader.close()
        finally:
            self._socket.close()


def hello(token: Optional[str], name: Optional[str], series: bool = False) -> dict:
    m = {"type": "hello", "version": VERSION}
    if series:
        m["series"] = True
    if token is not None:
        m["token"] = token
    if name is not None:
        m["name"] = name
    return m


def decisions(cycle: int, pairs) -> dict:
    return {"type": "decisions", "cycle": cycle, "decisions": [[int(v), int(t)] for v, t in pairs]}


def fault(cycle: int, kind: str, message: str) -> dict:
    return {"type": "decisions", "cycle": cycle, "fault": kind, "message": message[:1024]}


def _num(value) -> float:
    return float("nan") if value is None else float(value)


def _pair(value) -> Tuple[float, float]:
    return (_num(value[0]), _num(value[1]))
