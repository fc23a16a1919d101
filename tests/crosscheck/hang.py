#!/usr/bin/env python3
"""A solver that never ends, for geodex crosscheck's tests: it starts a child that also sleeps
(the whole process group must be killed, not only the shell) and waits.
    hang.py MESH.off SOURCE OUT.txt"""
import os
import subprocess
import sys
import time

print("hang.py: thinking", flush=True)
# The last argument marks the child, so that a test can see whether it outlived its case
# (HANG_MARKER: a marker of the test's own, when tests run side by side).
marker = os.environ.get("HANG_MARKER", "geodex-crosscheck-hang-child")
subprocess.Popen([sys.executable, "-c", "import time; time.sleep(3600)", marker])
time.sleep(3600)
