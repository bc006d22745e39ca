#!/usr/bin/env python3
"""Types each LINE and a Tab into a real interactive shell (bash or zsh, in a pseudo-terminal) with
epure's completion script loaded, and prints each line as the shell completed it, one a line:
completion as a user gets it, the shell's own word splitting (bash's at ':' and '=') included.

usage: tab_complete.py bash|zsh SCRIPT BINDIR LINE...

BINDIR is put first on PATH (the epure the script completes). The shell runs with no startup file,
HOME in a temporary directory, in the current directory; each line is read back through a key
bound to append the line buffer to a file (bash: bind -x and READLINE_LINE; zsh: a widget and
BUFFER), then erased (Ctrl-U) for the next."""
import os
import pty
import sys
import tempfile
import time


def lines_in(path):
    if not os.path.exists(path):
        return -1
    with open(path) as f:
        return f.read().count("\n")


def wait_for(path, child_fd, lines=0, seconds=20.0):
    """Until the file exists with `lines` complete lines, the terminal drained meanwhile."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if lines_in(path) >= lines:
            return True
        try:  # drain the terminal so that the shell never blocks on a full pty
            os.read(child_fd, 65536)
        except OSError:
            pass
        time.sleep(0.05)
    return False


def main():
    shell, script, bindir, lines = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    with tempfile.TemporaryDirectory() as home:
        ready, out = os.path.join(home, "ready"), os.path.join(home, "line")
        if shell == "bash":
            argv = ["bash", "--norc", "--noprofile", "-i"]
            setup = (f"source '{script}'; bind 'set bell-style none';"
                     f" bind -x '\"\\C-t\": printf \"%s\\n\" \"$READLINE_LINE\" >> {out}'; : > {ready}\n")
        else:
            argv = ["zsh", "-f", "-i"]
            setup = (f"fpath=('{os.path.dirname(script)}' $fpath); autoload -U compinit; compinit -u -D;"
                     f" unsetopt beep; write-line() {{ print -r -- \"$BUFFER\" >> {out} }};"
                     f" zle -N write-line; bindkey '^T' write-line; : > {ready}\n")
        env = dict(os.environ, HOME=home, TERM="dumb", PS1="$ ", PATH=bindir + os.pathsep + os.environ["PATH"])
        pid, fd = pty.fork()
        if pid == 0:
            os.execvpe(argv[0], argv, env)
        try:
            os.write(fd, setup.encode())
            if not wait_for(ready, fd):
                sys.exit(f"tab_complete: {shell} did not start")
            time.sleep(0.1)  # the prompt's line editor on (Ctrl-U in the terminal's own mode erases)
            for n, line in enumerate(lines, 1):
                # the line, Tab, the line handed back (Ctrl-T), erased (Ctrl-U): read in order
                os.write(fd, line.encode() + b"\t\x14\x15")
                if not wait_for(out, fd, n):
                    sys.exit(f"tab_complete: {shell} did not hand back '{line}'")
            with open(out) as f:
                sys.stdout.write(f.read())
        finally:
            os.kill(pid, 9)
            os.waitpid(pid, 0)


main()
