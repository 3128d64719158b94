"""play_series(): one connection, every match the server gives it (a tournament's remote entrant)."""

import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import unittest

from urwpgsim2d import Strategy, play, play_series
from urwpgsim2d.examples.chase_ball import ChaseBall

from .server import Server
from .test_client import ASSIGNMENT, CYCLE

HERE = os.path.dirname(os.path.abspath(__file__))


class Scripted:
    """A server of one connection that plays `matches` one-cycle matches and records every line the client sent.

    offer: whether the assignment says series (a server that keeps the connection); after the last
    match it reads the client's next hello, if one comes, and closes."""

    def __init__(self, matches: int, offer: bool):
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.received = []
        self.thread = threading.Thread(target=self._serve, args=(matches, offer), daemon=True)
        self.thread.start()

    def _serve(self, matches, offer):
        connection, _ = self.listener.accept()
        with connection, connection.makefile("rwb") as f:
            def read():
                line = f.readline()
                if line:
                    self.received.append(json.loads(line))
                return line

            def send(message):
                f.write(json.dumps(message).encode() + b"\n")
                f.flush()

            for m in range(matches):
                read()  # hello
                send(dict(ASSIGNMENT, series=offer))
                send(dict(CYCLE, cycle=m))
                read()  # decisions
                send({"type": "end", "cycle": 1, "goals": [m, 0], "faults": 0})
            connection.settimeout(5)
            try:
                read()  # a series client's next hello
            except OSError:
                pass
        self.listener.close()


class Fixed(Strategy):
    name = "fixed"

    def __init__(self):
        self.starts = 0

    def start(self, assignment):
        self.starts += 1

    def decide(self, snapshot):
        return [(1, 7)]


class Series(unittest.TestCase):
    def test_a_series_client_plays_every_match_on_one_connection_and_says_hello_after_each_end(self):
        server = Scripted(3, offer=True)
        strategy = Fixed()
        seen = []
        results = play_series(strategy, "127.0.0.1", server.port, ended=seen.append)
        server.thread.join(10)
        self.assertEqual([r.goals for r in results], [(0, 0), (1, 0), (2, 0)])
        self.assertEqual(seen, results)
        self.assertEqual(strategy.starts, 3)
        kinds = [(m["type"], m.get("cycle")) for m in server.received]
        self.assertEqual(kinds, [("hello", None), ("decisions", 0), ("hello", None), ("decisions", 1), ("hello", None), ("decisions", 2), ("hello", None)])
        self.assertTrue(all(m["series"] is True for m in server.received if m["type"] == "hello"))

    def test_a_server_that_does_not_offer_a_series_ends_it_after_one_match(self):
        server = Scripted(1, offer=False)
        results = play_series(Fixed(), "127.0.0.1", server.port)
        server.thread.join(10)
        self.assertEqual(len(results), 1)
        self.assertEqual([m["type"] for m in server.received], ["hello", "decisions"])  # no second hello: the old contract

    def test_play_says_no_series_and_plays_one_match(self):
        server = Scripted(1, offer=False)
        play(Fixed(), "127.0.0.1", server.port)
        server.thread.join(10)
        self.assertNotIn("series", server.received[0])


class Tournament(unittest.TestCase):
    def test_a_remote_entrant_plays_all_its_matches_with_one_client(self):
        with tempfile.TemporaryDirectory() as folder:
            server = Server("--item", "polo-1v1", "--entrant", "py=remote:0", "--entrant", "a=chase-ball", "--entrant", "b=idle",
                            "--seeds", "1", "--cycles", "30", "--strategy-timeout", "20000", "--out", folder, command="tournament")
            env = dict(os.environ, PYTHONPATH=os.path.dirname(HERE))
            client = subprocess.run([sys.executable, "-m", "urwpgsim2d.examples.chase_ball", "127.0.0.1:%d" % server.port], env=env, capture_output=True, text=True, timeout=600)
            code, out, err = server.finish()
            self.assertEqual(code, 0, out + err)
            self.assertEqual(client.returncode, 0, client.stderr)
            with open(os.path.join(folder, "results.jsonl"), encoding="utf-8") as f:
                records = [json.loads(line) for line in f][1:]
        mine = [r for r in records if "py" in r["entrants"]]
        self.assertGreaterEqual(len(mine), 2)
        self.assertTrue(all(r.get("kind") != "forfeit" for r in mine), mine)
        self.assertEqual(client.stdout.count("match ended after "), len(mine), client.stdout)  # a tied polo match plays on past its 30 cycles
        self.assertEqual(err.count('client "chase-ball (python)" connected'), 1, err)


if __name__ == "__main__":
    unittest.main()
