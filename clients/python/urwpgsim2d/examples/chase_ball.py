"""Chases the ball and pushes it towards the other team's goal.

    PYTHONPATH=clients/python python3 -m urwpgsim2d.examples.chase_ball HOST:PORT [--token T]
"""

import math
import sys

from urwpgsim2d import Strategy, main


def steer(fish, target):
    """(vcode, tcode) that swims fish towards target: turn harder the more it is off, slower when far off."""
    dx, dy = target[0] - fish.position[0], target[1] - fish.position[1]
    off = math.remainder(math.atan2(dy, dx) - fish.heading, math.tau)
    tcode = 7 + max(-7, min(7, round(off * 4)))
    vcode = 14 if abs(off) < 0.5 else 8 if abs(off) < 1.5 else 4
    return vcode, tcode


class ChaseBall(Strategy):
    """Each fish swims to a point behind its nearest ball (seen from the goal it attacks), then through the ball.

    With run --debug-draw it draws its plan: each fish's way to its aim, the ball's way to the goal
    (green), the ball circled (yellow) and what the fish is doing.
    """

    name = "chase-ball (python)"

    def decide(self, snapshot):
        a = snapshot.assignment
        # Team 0 attacks the right-hand goal until the halves swap ends.
        attack_right = (a.team == 0) != snapshot.sides_swapped
        goal = (a.field_length / 2 if attack_right else -a.field_length / 2, 0.0)
        answer = []
        for fish in snapshot.my_fish:
            if not snapshot.balls:
                answer.append((0, 7))
                continue
            ball = min(snapshot.balls, key=lambda b: math.dist(b.position, fish.position))
            gx, gy = goal[0] - ball.position[0], goal[1] - ball.position[1]
            norm = math.hypot(gx, gy) or 1.0
            behind = (ball.position[0] - gx / norm * (ball.radius + 60), ball.position[1] - gy / norm * (ball.radius + 60))
            lined_up = math.dist(fish.position, behind) < ball.radius + 80
            aim = goal if lined_up else behind
            answer.append(steer(fish, aim))
            if self.draw.on:  # shown with run --debug-draw
                self.draw.line(fish.position, aim, fish.index)
                self.draw.line(ball.position, goal, fish.index, 0x2E8B57)
                self.draw.circle(ball.position, ball.radius + 12, fish.index, 0xFFD400)
                self.draw.text((aim[0] + 20, aim[1] - 20), "push" if lined_up else "line up", fish.index)
        return answer


if __name__ == "__main__":
    sys.exit(main(ChaseBall()))
