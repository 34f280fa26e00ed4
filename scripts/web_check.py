"""Opens the harbor page in headless Chromium and checks what it reports.

    python3 scripts/web_check.py http://127.0.0.1:8765/?hs=0 [--seconds 20] [--screenshot out/web.png]

Drives Chromium through its DevTools protocol (a minimal WebSocket client: the standard library
only). Collects the page's console: every ``HARBOR {json}`` line the harbor logs once a second
(see ``crates/buoyancy-bevy/examples/harbor/web.rs``), and every error (a console error, an
uncaught exception, a failed load). Once the harbor's physics clock passes ``--seconds`` it takes
a screenshot and checks, from the last report:

* every body's height and draft are finite;
* in calm water (``hs`` 0), every body floats within 1 cm of its theoretical draft;
* no console error was logged.

It prints a table of the drafts, the mean frame time and the physics step's share of it, and
exits with status 1 if a check fails (2 if the page never reported).
"""

from __future__ import annotations

import argparse
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

TOLERANCE_M = 0.01


class WebSocket:
    """The client side of RFC 6455, enough for the DevTools protocol (text frames)."""

    def __init__(self, url: str) -> None:
        assert url.startswith("ws://")
        host_port, _, path = url[5:].partition("/")
        host, _, port = host_port.partition(":")
        self.sock = socket.create_connection((host, int(port)), timeout=30)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall(
            (
                f"GET /{path} HTTP/1.1\r\nHost: {host_port}\r\nUpgrade: websocket\r\n"
                f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
                "Sec-WebSocket-Version: 13\r\n\r\n"
            ).encode()
        )
        response = b""
        while b"\r\n\r\n" not in response:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise ConnectionError("the browser closed the connection during the handshake")
            response += chunk
        head, _, self.buffer = response.partition(b"\r\n\r\n")
        if b" 101 " not in head.split(b"\r\n", 1)[0]:
            raise ConnectionError(f"no WebSocket upgrade: {head[:200]!r}")

    def send(self, text: str) -> None:
        payload = text.encode()
        header = bytearray([0x81])
        n = len(payload)
        if n < 126:
            header.append(0x80 | n)
        elif n < 1 << 16:
            header.append(0x80 | 126)
            header += struct.pack(">H", n)
        else:
            header.append(0x80 | 127)
            header += struct.pack(">Q", n)
        mask = os.urandom(4)
        header += mask
        self.sock.sendall(bytes(header) + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def _read(self, n: int) -> bytes:
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise ConnectionError("the browser closed the connection")
            self.buffer += chunk
        data, self.buffer = self.buffer[:n], self.buffer[n:]
        return data

    def receive(self) -> str:
        """The next text message (fragments joined; pings answered)."""
        message = b""
        while True:
            first, second = self._read(2)
            opcode, n = first & 0x0F, second & 0x7F
            if n == 126:
                (n,) = struct.unpack(">H", self._read(2))
            elif n == 127:
                (n,) = struct.unpack(">Q", self._read(8))
            mask = self._read(4) if second & 0x80 else None
            payload = self._read(n)
            if mask:
                payload = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
            if opcode == 0x9:  # ping
                continue
            if opcode == 0x8:
                raise ConnectionError("the browser closed the connection")
            message += payload
            if first & 0x80:
                return message.decode()


class Browser:
    """Headless Chromium with one page, its console collected."""

    def __init__(self, url: str, size: tuple[int, int]) -> None:
        binary = shutil.which("chromium") or shutil.which("chromium-browser")
        if binary is None:
            sys.exit("web_check: no chromium on PATH (apt-get install chromium)")
        self.profile = tempfile.mkdtemp(prefix="harbor-chromium-")
        port = free_port()
        self.process = subprocess.Popen(
            [
                binary,
                "--headless=new",
                "--no-sandbox",
                "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader",
                "--no-first-run",
                "--disable-background-timer-throttling",
                "--disable-renderer-backgrounding",
                f"--window-size={size[0]},{size[1]}",
                f"--remote-debugging-port={port}",
                f"--user-data-dir={self.profile}",
                url,
            ],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        page = None
        for _ in range(100):
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=2) as r:
                    pages = [t for t in json.load(r) if t.get("type") == "page"]
                if pages:
                    page = pages[0]
                    break
            except OSError:
                pass
            time.sleep(0.2)
        if page is None:
            self.close()
            sys.exit("web_check: chromium did not open its DevTools port")
        self.ws = WebSocket(page["webSocketDebuggerUrl"])
        self.next_id = 0
        self.events: list[dict] = []
        for method in ("Runtime.enable", "Log.enable", "Page.enable"):
            self.call(method)

    def call(self, method: str, **params: object) -> dict:
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.ws.receive())
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})
            self.events.append(message)

    def event(self, timeout: float) -> dict | None:
        if self.events:
            return self.events.pop(0)
        self.ws.sock.settimeout(timeout)
        try:
            return json.loads(self.ws.receive())
        except TimeoutError:
            return None
        finally:
            self.ws.sock.settimeout(30)

    def close(self) -> None:
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def console_text(params: dict) -> str:
    return " ".join(str(a.get("value", a.get("description", a.get("type", "")))) for a in params.get("args", []))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("url")
    parser.add_argument("--seconds", type=float, default=20.0, help="physics time to wait for")
    parser.add_argument("--timeout", type=float, default=300.0, help="wall time allowed, s")
    parser.add_argument("--screenshot", default="out/web.png")
    parser.add_argument("--summary", help="also write the table and the timing to this Markdown file")
    args = parser.parse_args()

    browser = Browser(args.url, (1280, 720))
    reports: list[dict] = []
    errors: list[str] = []
    started = time.monotonic()
    try:
        while time.monotonic() - started < args.timeout:
            event = browser.event(timeout=1.0)
            if event is None:
                continue
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled":
                text = console_text(params)
                if text.startswith("HARBOR "):
                    report = json.loads(text[len("HARBOR ") :])
                    reports.append(report)
                    print(
                        f"  t {report['time']:6.1f} s  frame {report['frame_ms']:6.1f} ms  "
                        f"physics {report['physics_ms']:5.2f} ms ({report['steps']} steps)",
                        flush=True,
                    )
                    if report["time"] >= args.seconds:
                        break
                elif params.get("type") in ("error", "assert"):
                    errors.append(f"console.{params['type']}: {text}")
            elif method == "Runtime.exceptionThrown":
                details = params.get("exceptionDetails", {})
                text = details.get("exception", {}).get("description") or details.get("text")
                if "Using exceptions for control flow" not in str(text):
                    errors.append(f"uncaught exception: {text}")
            elif method == "Log.entryAdded":
                entry = params.get("entry", {})
                if entry.get("level") == "error":
                    errors.append(f"{entry.get('source')}: {entry.get('text')} {entry.get('url', '')}")
        if reports:
            shot = browser.call("Page.captureScreenshot", format="png")
            path = Path(args.screenshot)
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(base64.b64decode(shot["data"]))
            print(f"screenshot: {path}")
    finally:
        browser.close()

    if not reports:
        print("web_check: the page never reported (no HARBOR line on its console)")
        for e in errors:
            print(f"  {e}")
        return 2
    last = reports[-1]
    # The frame time over the reports after the first (the start-up's compilation excluded).
    steady = reports[1:] or reports
    frame_ms = sum(r["frame_ms"] for r in steady) / len(steady)
    physics_ms = sum(r["physics_ms"] for r in steady) / len(steady)
    steps = sum(r["steps"] for r in steady)
    step_ms = sum(r["step_ms"] * r["steps"] for r in steady) / max(steps, 1)
    calm = last["hs"] == 0
    failed = False
    summary = [
        f"Harbor page after {last['time']:.1f} s of physics ({'calm water' if calm else 'waves'}):",
        "",
        "| body | height m | draft m | theory m | Δ mm |",
        "|---|---|---|---|---|",
    ]
    for body in last["bodies"]:
        height, draft, theory = body["height"], body["draft"], body["theory"]
        problem = ""
        if height is None or draft is None:
            problem = " (not finite)"
        elif body["error"]:
            problem = f" ({body['error']})"
        elif calm and theory is not None and abs(draft - theory) > TOLERANCE_M:
            problem = " (over 10 mm)"
        failed |= bool(problem)
        delta = "" if draft is None or theory is None else f"{1e3 * (draft - theory):+.2f}"
        summary.append(
            f"| {body['name']} | {height} | {draft} | {theory if theory is not None else ''} | {delta}{problem} |"
        )
    summary.append(
        f"\nFrame {frame_ms:.1f} ms ({1e3 / frame_ms:.0f} frames/s); physics (the fixed 60 Hz "
        f"steps) {physics_ms:.2f} ms a frame ({100 * physics_ms / frame_ms:.1f} % of the frame), "
        f"{step_ms:.3f} ms a step; mean of {len(steady)} reports ({steps} steps)."
    )
    print("\n" + "\n".join(summary))
    if args.summary:
        Path(args.summary).write_text("\n".join(summary) + "\n")
    if errors:
        failed = True
        print(f"\n{len(errors)} console error(s):")
        for e in errors[:20]:
            print(f"  {e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
