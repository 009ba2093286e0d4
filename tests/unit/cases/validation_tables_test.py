#!/usr/bin/python3
"""The validation reports' tables against their records: for every case folder with records/tables.yaml, the
redraw command `cases/validation_tables.py CASE --check` must find each marked table of the case's README.md
equal to what it draws from the records (so that the prose and the records cannot drift apart). And the
command itself, on a case made here: a table drawn with its date and commit, a changed record or README cell
detected, a record no table lists refused, --write repairing the README."""
import glob
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
SCRIPT = os.path.join(ROOT, "cases", "validation_tables.py")


def redraw(case, *options):
    return subprocess.run([sys.executable, SCRIPT, case, *options], capture_output=True, text=True)


class ShippedReports(unittest.TestCase):
    def test_every_case_with_records_matches_them(self):
        cases = sorted(os.path.dirname(os.path.dirname(p))
                       for p in glob.glob(os.path.join(ROOT, "cases", "*", "records", "tables.yaml")))
        self.assertGreaterEqual(len(cases), 5, cases)
        for case in cases:
            with self.subTest(case=os.path.basename(case)):
                result = redraw(case, "--check")
                self.assertEqual(result.returncode, 0, result.stdout + result.stderr)


class Command(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="pf_validation_tables_")
        self.addCleanup(shutil.rmtree, self.folder)
        os.makedirs(os.path.join(self.folder, "records"))
        self.write("records/tables.yaml", "- name: heights\n  file: heights.csv\n  note: 2 ranks\n"
                   "  columns: [run, {key: [small, large], header: small / large}, {key: seg, format: '{:.2f}'}]\n")
        self.write("records/heights.csv", "run,small,large,seg,date,commit\nfine,48.8,32.0,0.418,2026-12-03,abc1234\n"
                   "np 8,50.1,26.4,0.619,2026-12-03,abc1234\n")
        self.write("README.md", "# case\n<!-- table heights -->\n<!-- end table -->\ntext\n")

    def write(self, name, text):
        with open(os.path.join(self.folder, name), "w") as f:
            f.write(text)

    def readme(self):
        with open(os.path.join(self.folder, "README.md")) as f:
            return f.read()

    def test_write_draws_the_table_with_its_date_and_commit_and_check_then_passes(self):
        self.assertNotEqual(redraw(self.folder, "--check").returncode, 0)  # the block is empty
        self.assertEqual(redraw(self.folder, "--write").returncode, 0)
        self.assertEqual(self.readme(), "# case\n<!-- table heights -->\n| run | small / large | seg |\n|---|---|---|\n"
                         "| fine | 48.8 / 32.0 | 0.42 |\n| np 8 | 50.1 / 26.4 | 0.62 |\n\n"
                         "Measured 2026-12-03 at commit abc1234 (2 ranks); record `heights.csv`.\n"
                         "<!-- end table -->\ntext\n")
        self.assertEqual(redraw(self.folder, "--check").returncode, 0)

    def test_a_changed_record_or_readme_cell_fails_the_check(self):
        redraw(self.folder, "--write")
        drawn = self.readme()
        self.write("README.md", drawn.replace("0.42", "0.43"))
        result = redraw(self.folder, "--check")
        self.assertEqual(result.returncode, 1)
        self.assertIn("table 'heights' differs from its record", result.stderr)
        self.write("README.md", drawn)
        self.write("records/heights.csv", "run,small,large,seg,date,commit\nfine,48.8,32.0,0.418,2026-12-03,abc1234\n"
                   "np 8,50.1,26.4,0.619,2026-12-04,def5678\n")
        self.assertEqual(redraw(self.folder, "--check").returncode, 1)  # dates differ: they become columns

    def test_rows_of_different_commits_carry_them_as_columns(self):
        self.write("records/heights.csv", "run,small,large,seg,date,commit\nfine,48.8,32.0,0.418,2026-12-03,abc1234\n"
                   "np 8,50.1,26.4,0.619,2026-12-04,def5678\n")
        result = redraw(self.folder)
        self.assertIn("| np 8 | 50.1 / 26.4 | 0.62 | 2026-12-04 | def5678 |", result.stdout)

    def test_an_unlisted_record_or_a_missing_commit_is_refused_naming_it(self):
        self.write("records/stray.csv", "a,b\n1,2\n")
        result = redraw(self.folder, "--check")
        self.assertEqual(result.returncode, 2)
        self.assertIn("stray.csv", result.stderr)
        os.remove(os.path.join(self.folder, "records", "stray.csv"))
        self.write("records/heights.csv", "run,small,large,seg\nfine,48.8,32.0,0.418\n")
        result = redraw(self.folder)
        self.assertEqual(result.returncode, 2)
        self.assertIn("has no 'commit'", result.stderr)


if __name__ == "__main__":
    unittest.main()
