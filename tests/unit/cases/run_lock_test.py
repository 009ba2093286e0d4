#!/usr/bin/env python3
"""run_lock.py of the Goldschmidt case: a folder whose .parcelflow.lock another open file holds (as a running
parcelflow does) is being written, and the drivers refuse it with status 2 naming the folder; a folder without a
lock file, or whose lock was released, is free."""
import fcntl
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "cases", "goldschmidt_segregation"))
import run_lock  # noqa: E402


def main():
    with tempfile.TemporaryDirectory(prefix="pf_run_lock_") as folder:
        assert not run_lock.writing(folder), "no lock file: free"
        assert not run_lock.writing(os.path.join(folder, "missing")), "no folder: free"
        holder = open(os.path.join(folder, run_lock.LOCK_FILE), "w")
        fcntl.flock(holder, fcntl.LOCK_EX | fcntl.LOCK_NB)  # what a running parcelflow holds
        assert run_lock.writing(folder), "held lock: writing"
        try:
            run_lock.refuse_if_writing([os.path.join(folder, "missing"), folder])
            raise AssertionError("refuse_if_writing did not exit")
        except SystemExit as e:
            assert folder in str(e.code) and "writing there" in str(e.code), e.code
            print(f"[message] {e.code}")
        fcntl.flock(holder, fcntl.LOCK_UN)
        holder.close()
        assert not run_lock.writing(folder), "released: free"
        run_lock.refuse_if_writing([folder])  # returns
    print("PASS")


if __name__ == "__main__":
    main()
