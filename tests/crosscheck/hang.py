#!/usr/bin/env python3
"""A solver that never ends, for geodex crosscheck's tests: it starts a child that also sleeps
(the whole process group must be killed, not only the shell) and waits.
    hang.py MESH.off SOURCE OUT.txt"""
import subprocess
import sys
import time

print("hang.py: thinking", flush=True)
# The last argument marks the child, so that a test can see whether it outlived its case.
subprocess.Popen([sys.executable, "-c", "import time; time.sleep(3600)", "geodex-crosscheck-hang-child"])
time.sleep(3600)
