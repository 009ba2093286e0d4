"""Whether a parcelflow run is writing into a folder: it holds an exclusive flock on FOLDER/.parcelflow.lock
while it runs (coupling/run/output_folder.h). A driver that clears a run folder before starting again
(coarse_graining.py) asks first: parcelflow's lock keeps a second run out of a folder, but
not a driver that deletes and recreates the folder under the first, whose later files then land among the
second's."""
import fcntl
import os
import sys

LOCK_FILE = ".parcelflow.lock"


def writing(folder):
    """True while a process holds the folder's parcelflow lock."""
    try:
        fd = os.open(os.path.join(folder, LOCK_FILE), os.O_RDONLY)
    except OSError:
        return False  # no lock file: no run has written there
    try:
        fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
        return False
    except BlockingIOError:
        return True
    finally:
        os.close(fd)


def refuse_if_writing(folders):
    """Exits (status 2) naming the first folder a run is writing into."""
    for folder in folders:
        if writing(folder):
            sys.exit(f"{folder}: a parcelflow run is writing there (it holds {LOCK_FILE}); wait for it or stop "
                     f"it before running this variant again")
