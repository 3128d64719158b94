"""Starts the built server for a test and reads the port a remote team waits on."""

import re
import subprocess

from urwpgsim2d.env import default_server

_WAITING = re.compile(r"waiting for a client on 127\.0\.0\.1:(\d+)")


class Server:
    """run ARGS... (or COMMAND ARGS...) with a remote team on a free port; .port once it waits; .finish() -> (exit code, stdout, stderr)."""

    def __init__(self, *args: str, command: str = "run"):
        self.process = subprocess.Popen(default_server() + [command, *args], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.lines = []
        for raw in self.process.stderr:
            line = raw.decode("utf-8", "replace")
            self.lines.append(line)
            m = _WAITING.search(line)
            if m:
                self.port = int(m.group(1))
                return
        self.finish()
        raise RuntimeError("the server did not wait for a client: " + "".join(self.lines))

    def finish(self):
        out, err = self.process.communicate(timeout=300)
        return self.process.returncode, out.decode("utf-8", "replace"), "".join(self.lines) + err.decode("utf-8", "replace")
