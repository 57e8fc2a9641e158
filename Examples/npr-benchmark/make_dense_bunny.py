#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the benchmark's 1M-triangle scene: the bunny (75,408 triangles) refined twice by Loop
subdivision (1,206,528 triangles), as a binary PLY. usage: make_dense_bunny.py BUNNY.ply OUT.ply"""
import sys

from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter

reader = vtkPLYReader()
reader.SetFileName(sys.argv[1])
clean = vtkCleanPolyData()
clean.SetInputConnection(reader.GetOutputPort())
refine = vtkLoopSubdivisionFilter()
refine.SetInputConnection(clean.GetOutputPort())
refine.SetNumberOfSubdivisions(2)
writer = vtkPLYWriter()
writer.SetInputConnection(refine.GetOutputPort())
writer.SetFileName(sys.argv[2])
writer.SetFileTypeToBinary()
if not writer.Write():
    sys.exit("cannot write " + sys.argv[2])
