#!/usr/bin/env python3
"""A solver that writes one line too few, for geodex crosscheck's tests: the distances of every
vertex but the last, each as 0.   short_output.py MESH.off SOURCE OUT.txt"""
import sys

words = open(sys.argv[1]).read().split()
vertices = int(words[1])
with open(sys.argv[3], "w") as f:
    f.writelines("0\n" for _ in range(vertices - 1))
