// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The OpenGL declarations of the VTK in use, through the loader VTK itself uses: GLEW
 * (`vtk_glew.h`) up to VTK 9.3, glad (`vtk_glad.h`) from VTK 9.4 on. The passes call only
 * OpenGL core functions, which both declare alike; include this header, never one of the two.
 */
#ifndef vtkNPROpenGL_h
#define vtkNPROpenGL_h

#if __has_include("vtk_glad.h")
#include "vtk_glad.h" // IWYU pragma: export
#define NPR_GL_LOADER_GLAD 1
#else
#include "vtk_glew.h" // IWYU pragma: export
#define NPR_GL_LOADER_GLAD 0
#endif

#endif
// VTK-HeaderTest-Exclude: vtkNPROpenGL.h
