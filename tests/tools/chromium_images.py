#!/usr/bin/python3
"""Opens an HTML file in headless Chromium and prints "IMAGES RENDERED": how many <img> elements the page has
and how many of them Chromium decoded and laid out (complete, with a natural width), after the load event.

usage: chromium_images.py FILE.html
Speaks the DevTools protocol over --remote-debugging-pipe (file descriptors 3 and 4, NUL-separated JSON), so
it needs nothing beyond the standard library and Debian's chromium package. Exits 2 when chromium is not
installed (the caller skips, saying so), 1 when the page does not load within 60 s.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

COUNT = ("JSON.stringify([document.images.length, "
         "Array.from(document.images).filter(i => i.complete && i.naturalWidth > 0).length])")


def main(path):
    chromium = shutil.which("chromium")
    if not chromium:
        print("chromium is not installed (Debian: apt-get install chromium)", file=sys.stderr)
        return 2
    commands_r, commands_w = os.pipe()
    replies_r, replies_w = os.pipe()
    profile = tempfile.mkdtemp()

    def as_child():
        os.dup2(commands_r, 3)
        os.dup2(replies_w, 4)

    browser = subprocess.Popen([chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
                                f"--user-data-dir={profile}", "about:blank"], pass_fds=(3, 4), preexec_fn=as_child,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(commands_r)
    os.close(replies_w)
    state = {"id": 0, "buffer": b""}

    def send(method, params=None, session=None):
        state["id"] += 1
        message = {"id": state["id"], "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(commands_w, json.dumps(message).encode() + b"\0")
        return state["id"]

    def wait_for(matches, deadline):
        while time.time() < deadline:
            while b"\0" in state["buffer"]:
                raw, state["buffer"] = state["buffer"].split(b"\0", 1)
                message = json.loads(raw)
                if matches(message):
                    return message
            chunk = os.read(replies_r, 65536)
            if not chunk:
                break
            state["buffer"] += chunk
        raise TimeoutError

    try:
        deadline = time.time() + 60
        sent = send("Target.createTarget", {"url": "about:blank"})
        target = wait_for(lambda m: m.get("id") == sent, deadline)["result"]["targetId"]
        sent = send("Target.attachToTarget", {"targetId": target, "flatten": True})
        session = wait_for(lambda m: m.get("id") == sent, deadline)["result"]["sessionId"]
        send("Page.enable", session=session)
        send("Page.navigate", {"url": "file://" + os.path.abspath(path)}, session=session)
        wait_for(lambda m: m.get("method") == "Page.loadEventFired", deadline)
        sent = send("Runtime.evaluate", {"expression": COUNT, "returnByValue": True}, session=session)
        images, rendered = json.loads(wait_for(lambda m: m.get("id") == sent, deadline)["result"]["result"]["value"])
        print(images, rendered)
        return 0
    except (TimeoutError, KeyError, ValueError) as e:
        print(f"chromium_images: {path} did not load: {e!r}", file=sys.stderr)
        return 1
    finally:
        browser.kill()
        browser.wait()
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
