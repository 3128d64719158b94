import json
import math
import subprocess
import tempfile
import sys
import os
import unittest

from urwpgsim2d import Assignment, Refused, Snapshot, Strategy, parse_address, play
from urwpgsim2d.client import _answer
from urwpgsim2d.examples.chase_ball import ChaseBall

from .server import Server

HERE = os.path.dirname(os.path.abspath(__file__))
ASSIGNMENT = json.loads('{"type":"assignment","version":1,"team":1,"item":"polo-1v1","itemName":"x","fish":[1],"fishCount":2,"ballCount":1,'
                        '"totalCycles":600,"cycleMs":100,"deadlineMs":100,"field":{"length":3000,"width":2000,"goalWidth":400,"goalDepth":150},'
                        '"obstacles":[{"index":0,"kind":"round","center":[1,2],"length":0,"width":0,"heading":0,"radius":50}],"future":1}')
FISH = '{"index":%d,"team":%d,"position":[%s,0],"heading":0,"speed":0,"angularSpeed":0,"bodyLength":160,"headLength":30,"width":45,"joints":[0,0,0],"tailLengths":[1,2,3],"decision":[0,7]}'
CYCLE = json.loads('{"type":"cycle","cycle":12,"goals":[0,1],"sidesSwapped":true,"variables":{"phase":"second half"},"fish":[%s,%s],'
                   '"balls":[{"index":0,"position":[0,0],"velocity":[null,0],"radius":58}],"unknown":{"a":[]}}' % (FISH % (0, 0, "-500"), FISH % (1, 1, "500")))


class Messages(unittest.TestCase):
    def test_a_snapshot_reads_every_field_ignores_unknown_ones_and_maps_null_to_nan(self):
        a = Assignment.from_json(ASSIGNMENT)
        s = Snapshot.from_json(CYCLE, a)
        self.assertEqual((a.team, a.fish, a.field_length, a.obstacles[0].kind), (1, [1], 3000.0, "round"))
        self.assertEqual((s.cycle, s.goals, s.sides_swapped, s.variables), (12, (0, 1), True, {"phase": "second half"}))
        self.assertEqual(s.my_fish[0].position, (500.0, 0.0))
        self.assertAlmostEqual(s.time, 1.2)
        self.assertNotEqual(s.balls[0].velocity[0], s.balls[0].velocity[0])  # NaN

    def test_a_four_team_item_carries_four_scores(self):
        four = dict(CYCLE, goals=[0, 1, 2, 3])
        self.assertEqual(Snapshot.from_json(four, Assignment.from_json(dict(ASSIGNMENT, team=3))).goals, (0, 1, 2, 3))

    def test_an_answer_is_decisions_or_that_cycles_fault(self):
        s = Snapshot.from_json(CYCLE, Assignment.from_json(ASSIGNMENT))

        class Fixed(Strategy):
            def __init__(self, result):
                self.result = result

            def decide(self, snapshot):
                if isinstance(self.result, Exception):
                    raise self.result
                return self.result

        self.assertEqual(_answer(Fixed([(14, 7)]), s, 1), {"type": "decisions", "cycle": 12, "decisions": [[14, 7]]})
        self.assertEqual(_answer(Fixed(KeyError("x")), s, 1)["fault"], "exception")
        for bad in ([(16, 7)], [(1, 2), (3, 4)], [(1.5, 2)], [(True, 2)], 5, [("a", 1)]):
            self.assertEqual(_answer(Fixed(bad), s, 1)["fault"], "badAnswer", bad)

    def test_drawings_and_output_go_with_the_answer_only_when_the_server_asks(self):
        a = Assignment.from_json(dict(ASSIGNMENT, draw=True, log=True))
        s = Snapshot.from_json(CYCLE, a)

        class Drawer(Strategy):
            def decide(self, snapshot):
                print("saw cycle", snapshot.cycle)
                print("to stderr", file=sys.stderr)
                self.draw.line((0, 0), (10, 20), 1)
                self.draw.circle((1, 2), 3, 0, "#FFD400")  # fish 0 is not this team's: the team's shape
                self.draw.point((float("nan"), 0))  # not finite: dropped
                self.draw.text((5, 5), "a" * 5000, colour=0x2E8B57)
                for i in range(200):
                    self.draw.point((i, 0))
                return [(14, 7)]

        answer = _answer(Drawer(), s, 1, a.draw, a.log)
        self.assertEqual(answer["decisions"], [[14, 7]])
        self.assertEqual(answer["log"], "saw cycle 12\nto stderr\n")
        self.assertEqual(answer["logDropped"], 0)
        shapes = answer["draw"]
        self.assertEqual(len(shapes), 128)
        self.assertEqual(shapes[0], {"kind": "line", "from": [0.0, 0.0], "to": [10.0, 20.0], "fish": 1})
        self.assertEqual(shapes[1], {"kind": "circle", "center": [1.0, 2.0], "radius": 3.0, "color": "#ffd400"})
        self.assertEqual(shapes[2], {"kind": "text", "at": [5.0, 5.0], "text": "a" * 4096, "color": "#2e8b57"})

        quiet = _answer(Drawer(), Snapshot.from_json(CYCLE, Assignment.from_json(ASSIGNMENT)), 1)
        self.assertEqual(quiet, {"type": "decisions", "cycle": 12, "decisions": [[14, 7]]})

    def test_addresses(self):
        self.assertEqual(parse_address("127.0.0.1:7000"), ("127.0.0.1", 7000))
        self.assertEqual(parse_address("[::1]:7000"), ("::1", 7000))
        for bad in ("127.0.0.1", ":7000", "h:0", "h:x"):
            with self.assertRaises(ValueError):
                parse_address(bad)


class Matches(unittest.TestCase):
    def test_the_chase_ball_example_plays_a_match_to_the_end_with_no_fault(self):
        server = Server("--item", "polo-1v1", "--cycles", "150", "--seed", "4", "--strategy", "0=remote:0", "--strategy", "1=chase-ball", "--strategy-timeout", "20000")
        env = dict(os.environ, PYTHONPATH=os.path.dirname(HERE))
        client = subprocess.run([sys.executable, "-m", "urwpgsim2d.examples.chase_ball", "127.0.0.1:%d" % server.port], env=env, capture_output=True, text=True, timeout=300)
        code, out, err = server.finish()
        self.assertEqual(client.returncode, 0, client.stderr)
        self.assertRegex(client.stdout, r"^match ended after \d+ cycles: \d+:\d+, 0 fault\(s\) charged to this team\n$")
        self.assertEqual(code, 0, err)
        self.assertIn("strategy faults: none", out)
        self.assertIn('client "chase-ball (python)" connected', err)

    def test_a_strategy_that_throws_is_charged_and_the_match_goes_on(self):
        class Clumsy(ChaseBall):
            def decide(self, snapshot):
                if snapshot.cycle % 10 == 3:
                    raise ZeroDivisionError("oops")
                return super().decide(snapshot)

        server = Server("--item", "default", "--cycles", "40", "--strategy", "0=remote:0", "--strategy-timeout", "20000", "--remote-token", "t")
        result = play(Clumsy(), "127.0.0.1", server.port, token="t")
        code, out, err = server.finish()
        self.assertEqual(code, 0, err)
        self.assertEqual(result.faults, 4)
        self.assertNotIn("strategy faults: none", out)

    def test_drawings_and_printed_output_reach_the_trace_over_tcp(self):
        class Talker(ChaseBall):
            def decide(self, snapshot):
                print("cycle", snapshot.cycle)
                return super().decide(snapshot)

        with tempfile.TemporaryDirectory() as folder:
            trace = os.path.join(folder, "t.jsonl")
            server = Server("--item", "default", "--cycles", "30", "--noise", "off", "--strategy", "0=remote:0", "--strategy-timeout", "20000",
                            "--debug-draw", "--strategy-log", "--trace", trace)
            result = play(Talker(), "127.0.0.1", server.port)
            code, _, err = server.finish()
            self.assertEqual(code, 0, err)
            self.assertEqual(result.faults, 0)
            with open(trace, encoding="utf-8") as f:
                lines = [json.loads(line) for line in f]
        mine = [i for i, fish in enumerate(lines[0]["layout"]["fish"]) if fish["team"] == 0]
        for n in range(1, len(lines)):
            self.assertEqual([l for l in lines[n]["log"] if l["team"] == 0], [{"team": 0, "text": "cycle %d\n" % (n - 1)}])
            drawn = [d for d in lines[n]["draw"] if d["team"] == 0]
            self.assertEqual(sorted({d["fish"] for d in drawn}), mine)
            for i in mine:
                # The ball circled is the one nearest the fish in the snapshot it decided from (noise off: the line before).
                seen = lines[n - 1]
                at = seen["fish"][i]["position"]
                ball = min(seen["balls"], key=lambda b: math.dist(b["position"], at))
                circle = [d for d in drawn if d["fish"] == i and d["kind"] == "circle"]
                self.assertEqual(len(circle), 1)
                self.assertEqual(circle[0]["center"], ball["position"])
                self.assertEqual(circle[0]["color"], "#ffd400")
                way = [d for d in drawn if d["fish"] == i and d["kind"] == "line" and "color" not in d]
                self.assertEqual(way[0]["from"], at)

    def test_a_wrong_token_is_refused(self):
        server = Server("--cycles", "5", "--strategy", "1=remote:0", "--remote-token", "right", "--remote-wait", "30")
        with self.assertRaises(Refused) as refused:
            play(ChaseBall(), "127.0.0.1", server.port, token="wrong")
        self.assertEqual(str(refused.exception), "wrong token")
        play(ChaseBall(), "127.0.0.1", server.port, token="right")
        code, _, err = server.finish()
        self.assertEqual(code, 0, err)
        self.assertIn("refused a client: wrong token", err)


if __name__ == "__main__":
    unittest.main()
