"""Finding the carom command and running it, with carom's one-line errors raised as Python exceptions."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import threading
from pathlib import Path
from typing import Callable, List, Optional, Sequence, Union

PathLike = Union[str, "os.PathLike[str]"]
#: What may receive carom's stderr as it runs: True echoes it to this process's stderr.
Progress = Union[bool, Callable[[str], None]]


class CaromError(Exception):
    """carom refused its input or failed.

    ``message`` is carom's one ``error:`` line without that prefix (the file, the JSON path or the
    option, and what is wrong, exactly as the command line prints it), ``status`` its exit status (2:
    bad input you can fix; 1: a failure of carom or the machine; 130 or 143: stopped by SIGINT or
    SIGTERM), ``stderr`` all it printed there and ``command`` the command line that ran.
    """

    def __init__(self, message: str, status: int, stderr: str, command: Sequence[str]):
        super().__init__(message)
        self.message = message
        self.status = status
        self.stderr = stderr
        self.command = list(command)

    def __str__(self) -> str:
        return f"{self.message} (carom exit status {self.status})"


def find_command(carom: Optional[PathLike] = None) -> List[str]:
    """The command line that starts carom, the first found of:

    1. ``carom`` if given: the path of the ``carom`` launcher (or of any program taking carom's
       arguments), or of a jar (a name ending in ``.jar``, such as ``app/target/carom.jar``);
    2. the environment variable ``CAROM``, the same;
    3. the launcher of the repository this package sits in (an editable install, ``pip install -e``);
    4. a ``carom`` launcher in the current folder or a folder above it (a clone of the repository);
    5. ``carom`` on the ``PATH``.

    A jar runs as ``java -jar JAR``, with ``$JAVA_HOME/bin/java`` if ``JAVA_HOME`` is set, else the
    ``java`` on the ``PATH`` (carom needs 21 or newer). Raises ``FileNotFoundError`` when none is found.
    """
    given = carom if carom is not None else os.environ.get("CAROM")
    if given:
        return _command_for(Path(given))
    # src/carom/_command.py of python/ in a clone: three folders up is the clone's root.
    candidates = [Path(__file__).resolve().parents[3]]
    cwd = Path.cwd().resolve()
    candidates += [cwd, *cwd.parents]
    for folder in candidates:
        launcher = folder / "carom"
        if launcher.is_file() and os.access(launcher, os.X_OK) and (folder / "pom.xml").is_file():
            return [str(launcher)]
    on_path = shutil.which("carom")
    if on_path:
        return [on_path]
    raise FileNotFoundError(
        "carom not found: pass carom=PATH (the repository's ./carom launcher or app/target/carom.jar), "
        "set CAROM, or run from inside a clone of the repository")


def _command_for(path: Path) -> List[str]:
    if path.suffix == ".jar":
        if not path.is_file():
            raise FileNotFoundError(f"carom jar not found: {path}")
        home = os.environ.get("JAVA_HOME")
        java = str(Path(home) / "bin" / "java") if home else shutil.which("java")
        if not java:
            raise FileNotFoundError("no java to run the carom jar: set JAVA_HOME or put java on the PATH")
        return [java, "--enable-native-access=ALL-UNNAMED", "-jar", str(path)]
    if not path.is_file():
        raise FileNotFoundError(f"carom not found: {path}")
    return [str(path)]


def run_carom(arguments: Sequence[PathLike], *, carom: Optional[PathLike] = None, cwd: Optional[PathLike] = None,
              progress: Progress = False) -> str:
    """Runs carom with ``arguments`` and returns what it printed on stdout.

    carom's stderr (its progress and status lines, build messages of the launcher's first use) goes,
    line by line as it comes, to ``progress``: a function of one line, or this process's stderr if
    ``progress`` is True. A non-zero exit raises :class:`CaromError` with carom's ``error:`` line. The
    child never outlives the call: on an exception here (Ctrl-C included) it gets SIGINT, so a run with a
    checkpoint saves it, and is killed if it has not stopped within a minute.
    """
    command = find_command(carom) + [str(a) for a in arguments]
    echo: Optional[Callable[[str], None]]
    if progress is True:
        echo = _echo
    elif callable(progress):
        echo = progress
    else:
        echo = None
    child = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, encoding="utf-8", errors="replace")
    stdout, stderr = child.stdout, child.stderr
    assert stdout is not None and stderr is not None
    lines: List[str] = []

    def read_stderr() -> None:
        for line in stderr:
            line = line.rstrip("\n")
            lines.append(line)
            if echo is not None:
                echo(line)

    reader = threading.Thread(target=read_stderr, daemon=True)
    reader.start()
    try:
        out = stdout.read()
        status = child.wait()
    finally:
        if child.poll() is None:
            child.send_signal(signal.SIGINT)  # carom saves a checkpoint if it has one, and stops
            try:
                child.wait(timeout=60)
            except subprocess.TimeoutExpired:
                child.kill()
                child.wait()
        reader.join()
        stdout.close()
        stderr.close()
    if status != 0:
        raise CaromError(_error_line(lines, status), status, "\n".join(lines), command)
    return out


def _echo(line: str) -> None:
    print(line, file=sys.stderr, flush=True)


def _error_line(lines: Sequence[str], status: int) -> str:
    for line in lines:
        if line.startswith("error: "):
            return line[len("error: "):]
    last = next((line for line in reversed(lines) if line.strip()), None)
    return last if last is not None else f"carom stopped with exit status {status} and said nothing"
