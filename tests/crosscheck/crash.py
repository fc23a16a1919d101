#!/usr/bin/env python3
"""A solver that crashes, for geodex crosscheck's tests: it says why on stderr, then aborts
(SIGABRT) without writing its output.    crash.py MESH.off SOURCE OUT.txt"""
import os
import sys

print(f"crash.py: giving up on {sys.argv[1]}", file=sys.stderr, flush=True)
os.abort()
