"""A strategy base class and the loop that plays it for a server that waits for a remote team."""

import contextlib
import sys
from typing import Callable, List, Optional, Sequence, Tuple

from . import protocol
from .drawing import Drawing, Output
from .protocol import Assignment, End, ProtocolError, Snapshot, goals_of


class Refused(Exception):
    """The server refused the client (wrong token, another protocol version)."""


class Strategy:
    """A team's strategy: override decide(); start() and end() are optional."""

    name: Optional[str] = None
    """The team's name, sent in the hello."""

    draw: Drawing = Drawing()
    """This cycle's debug drawings (self.draw.line(...), see urwpgsim2d.drawing): sent with the
    decisions when the server records them (run --debug-draw); otherwise every call does nothing."""

    def start(self, assignment: Assignment) -> None:
        """Called once a connection has its assignment (again after a reconnect, and for each match of a series)."""

    def decide(self, snapshot: Snapshot) -> Sequence[Tuple[int, int]]:
        """One (vcode, tcode) pair, each 0..15, per fish of snapshot.my_fish, in that order."""
        raise NotImplementedError

    def end(self, result: End) -> None:
        """Called with the server's end of the match."""


def play(strategy: Strategy, host: str, port: int, token: Optional[str] = None, timeout: float = 10.0) -> End:
    """Connects, plays every cycle with strategy.decide until the end, and returns the result.

    A decide() that raises is answered as that cycle's 'exception' fault, and one that returns
    something unusable as a 'badAnswer' fault (the server keeps the fish's last decisions); the
    match goes on. When the server asks (run --debug-draw, --strategy-log), the cycle's drawings
    (self.draw) and what decide() printed (sys.stdout and sys.stderr) go with the answer. Raises Refused when the server refuses the hello, ProtocolError when it breaks
    the protocol or closes the connection before the end.
    """
    connection = protocol.Connection(host, port, timeout)
    try:
        connection.send(protocol.hello(token, strategy.name))
        first = connection.receive()
        if first is None:
            raise ProtocolError("the server closed the connection before the assignment")
        return _match(connection, strategy, first)[0]
    finally:
        connection.close()


def play_series(strategy: Strategy, host: str, port: int, token: Optional[str] = None, timeout: float = 10.0,
                ended: Optional[Callable[[End], None]] = None) -> List[End]:
    """Connects once and plays every match the server gives the connection; returns each match's result.

    The hello says "series": true, so a server that plays several matches with this client (a
    tournament's remote entrant, tournament --entrant NAME=remote:PORT) keeps the connection after
    each end: the client says hello again and waits for the next assignment (strategy.start() is
    called for each match). When the server closes the connection after an end (or never offered a
    next match), the series is over. ended, if given, is called with each match's result as it
    ends. Raises as play() does.
    """
    connection = protocol.Connection(host, port, timeout)
    results: List[End] = []
    try:
        while True:
            try:
                connection.send(protocol.hello(token, strategy.name, series=True))
                first = connection.receive()
            except OSError:
                if results:
                    return results  # closed (with a reset) after the last end
                raise
            if first is None:
                if results:
                    return results  # no next match
                raise ProtocolError("the server closed the connection before the assignment")
            result, more = _match(connection, strategy, first)
            results.append(result)
            if ended is not None:
                ended(result)
            if not more:
                return results
    finally:
        connection.close()


def _match(connection: "protocol.Connection", strategy: Strategy, first: dict) -> Tuple[End, bool]:
    """One match from its assignment (first) to its end: the result, and whether the server keeps the connection for another."""
    if first["type"] == "error":
        raise Refused(str(first.get("message", "")))
    if first["type"] != "assignment":
        raise ProtocolError("expected an assignment, got %r" % first["type"])
    assignment = Assignment.from_json(first)
    strategy.start(assignment)
    while True:
        message = connection.receive()
        if message is None:
            raise ProtocolError("the server closed the connection before the end of the match")
        kind = message["type"]
        if kind == "cycle":
            snapshot = Snapshot.from_json(message, assignment)
            connection.send(_answer(strategy, snapshot, len(assignment.fish), assignment.draw, assignment.log))
        elif kind == "end":
            result = End(int(message["cycle"]), goals_of(message), int(message["faults"]))
            strategy.end(result)
            return result, assignment.series
        elif kind == "error":
            raise ProtocolError("the server ended the connection: %s" % message.get("message", ""))
        # another message of a later version: not needed here


def _answer(strategy: Strategy, snapshot: Snapshot, count: int, draw: bool = False, log: bool = False) -> dict:
    drawing = Drawing(draw, snapshot.assignment.fish)
    strategy.draw = drawing
    output = Output() if log else None
    answer = _decide(strategy, snapshot, count, output)
    strategy.draw = Strategy.draw
    if drawing.shapes and (answer.get("fault") in (None, "exception")):
        answer["draw"] = drawing.shapes
    if output is not None and (output.text() or output.dropped):
        answer["log"] = output.text()
        answer["logDropped"] = output.dropped
    return answer


def _decide(strategy: Strategy, snapshot: Snapshot, count: int, output: Optional[Output]) -> dict:
    try:
        if output is None:
            pairs = strategy.decide(snapshot)
        else:
            with contextlib.redirect_stdout(output), contextlib.redirect_stderr(output):
                pairs = strategy.decide(snapshot)
    except Exception as e:  # the strategy's fault, reported to the server; the match goes on
        return protocol.fault(snapshot.cycle, "exception", "%s: %s" % (type(e).__name__, e))
    checked: List[Tuple[int, int]] = []
    try:
        for v, t in pairs:
            if isinstance(v, bool) or isinstance(t, bool) or int(v) != v or int(t) != t or not (0 <= v <= 15 and 0 <= t <= 15):
                raise ValueError("gears must be integers 0..15, got (%r, %r)" % (v, t))
            checked.append((int(v), int(t)))
    except (TypeError, ValueError) as e:
        return protocol.fault(snapshot.cycle, "badAnswer", str(e))
    if len(checked) != count:
        return protocol.fault(snapshot.cycle, "badAnswer", "%d decisions for %d fish" % (len(checked), count))
    return protocol.decisions(snapshot.cycle, checked)


def parse_address(text: str) -> Tuple[str, int]:
    """HOST:PORT (IPv6 in brackets) as (host, port)."""
    host, sep, port = text.rpartition(":")
    host = host.strip("[]")
    if not sep or not host or not port.isdigit() or not 1 <= int(port) <= 65535:
        raise ValueError("HOST:PORT must be a host and a port 1..65535, got %r" % text)
    return host, int(port)


def main(strategy: Strategy, argv: Optional[List[str]] = None) -> int:
    """Command line of a strategy module: HOST:PORT [--token T]. Plays every match the server gives the
    connection (play_series), one line per match on stdout. Exit codes as the server's connect."""
    import argparse

    parser = argparse.ArgumentParser(description="Play %s for a server that waits for a remote team." % (strategy.name or "a strategy"))
    parser.add_argument("address", metavar="HOST:PORT")
    parser.add_argument("--token", default=None, help="the token the server was given (--remote-token)")
    args = parser.parse_args(argv)
    try:
        host, port = parse_address(args.address)
    except ValueError as e:
        parser.error(str(e))
    def ended(result: End) -> None:
        print("match ended after %d cycles: %s, %d fault(s) charged to this team" % (result.cycle, ":".join(str(g) for g in result.goals), result.faults), flush=True)

    try:
        play_series(strategy, host, port, args.token, ended=ended)
    except Refused as e:
        print("the server refused the client: %s" % e, file=sys.stderr)
        return 6
    except (ProtocolError, OSError) as e:
        print("connection: %s" % e, file=sys.stderr)
        return 5
    return 0
