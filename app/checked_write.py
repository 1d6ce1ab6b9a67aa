"""The Python twin of renderer/checked_write.h, for the lab's scripts (bench_charts.py, the window soak):
a file is written to a temporary file in its folder, flushed, fsynced and renamed over its name, so it
holds all of what was written or what it held before; a target that is not a regular file (/dev/full, a
FIFO) is written in place. A failure exits the script non-zero, naming the file and the reason."""
import os
import stat
import sys
import tempfile


def write_with(path, write, mode="wb"):
    """Calls write(f) on a file that becomes `path` only once all of it is on disk."""
    try:
        target = os.path.realpath(path)  # a symbolic link keeps pointing at the replaced file
        if os.path.exists(target) and not stat.S_ISREG(os.stat(target).st_mode):
            with open(target, mode) as f:
                write(f)
            return
        fd, temp = tempfile.mkstemp(dir=os.path.dirname(target) or ".",
                                    prefix="." + os.path.basename(target) + ".")
    except OSError as e:
        sys.exit(f"cannot write {path}: {e.strerror or e}")
    try:
        with os.fdopen(fd, mode) as f:
            write(f)
            f.flush()
            os.fsync(f.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temp, 0o666 & ~umask)  # what open() would give, not mkstemp's 0600
        os.replace(temp, target)
    except OSError as e:
        try:
            os.unlink(temp)
        except OSError:
            pass
        sys.exit(f"cannot write {path}: {e.strerror or e}")


def write_text(path, text):
    write_with(path, lambda f: f.write(text), mode="w")
