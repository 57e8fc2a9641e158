// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
  // vtkNPRGBufferPass: geometry attachment = (view depth, packed normal, object id, packed face
  // normal), or
  // another encoding of them (vtkNPRGBufferPass::GeometryEncoding).
  {
#if NPR_HAVE_VERTEX_VC
    float nprDepth = -vertexVCVSOutput.z / vertexVCVSOutput.w;
#else
    float nprDepth = -nprFragmentPositionVC().z;
#endif
#if NPR_ENCODING == 1
    // Half: the depth over the far clipping distance, so that any scene's depths stay in half's
    // range (the lines use depth ratios only). Still above 0, the background.
    vec4 nprGeometry = vec4(max(nprDepth / nprDepthRange.y, 1e-7), 0.0, 0.0, 0.0);
#else
    vec4 nprGeometry = vec4(max(nprDepth, 1e-30), 0.0, 0.0, 1.0);
#endif
#if NPR_WRITE_NORMALS
    // The view-space position, once for both uses below: interpolated where the mapper passes it
    // (rebuilding it from gl_FragCoord costs llvmpipe about a quarter of this shader's time).
#if NPR_HAVE_VERTEX_VC
    vec3 nprPositionVC = vertexVCVSOutput.xyz / vertexVCVSOutput.w;
#else
    vec3 nprPositionVC = nprFragmentPositionVC();
#endif
#if NPR_PERSPECTIVE
    vec3 nprToViewer = -nprPositionVC;
#else
    vec3 nprToViewer = vec3(0.0, 0.0, 1.0);
#endif
#if NPR_HAVE_MAPPER_NORMAL
    vec3 nprNormal = normalVCVSOutput;
    // VTK turns the normal of a back-facing fragment around (two-sided lighting). Where the
    // winding disagrees with the normals, as for a needle triangle whose winding flips when its
    // points are rounded to 32-bit floats, or a mesh oriented inwards, that turns it away from
    // the viewer: turn it back. (So n.v keeps its sign on front-facing fragments only: the smooth
    // silhouettes' sign changes are those of the front-facing triangles, the depth step the rest.)
    if (!gl_FrontFacing && dot(nprNormal, nprToViewer) < 0.0)
    {
      nprNormal = -nprNormal;
    }
#else
    vec3 nprNormal = vec3(0.0);
#endif
    // Unlit actors, lines, points and zero-length or NaN normals: the face normal.
    if (!(dot(nprNormal, nprNormal) > 1e-12))
    {
      nprNormal = nprFaceNormal(nprPositionVC, nprToViewer);
    }
    nprNormal = normalize(nprNormal);
#if NPR_ENCODING == 1
    nprGeometry.yz = nprOctahedral(nprNormal);
#else
    nprGeometry.y = nprPackNormal(nprNormal);
#endif
#if NPR_WRITE_FACE_NORMALS
    // The face normal too, on the side of the interpolated one: creases are angles between faces,
    // as in the mesh, whatever the shading normals average across (vtkNPREdgePass).
    vec3 nprFace = nprFaceNormal(nprPositionVC, nprToViewer);
    nprGeometry.w = nprPackNormal(nprFace * sign(dot(nprFace, nprNormal) + 1e-30));
#endif
#endif
#if NPR_WRITE_OBJECT_IDS
#if NPR_ENCODING == 1
    nprGeometry.w = nprObjectId;
#else
    nprGeometry.z = nprObjectId;
#endif
#endif
#if NPR_ENCODING >= 2
    // Packed: 1 + depth + nx + ny + nz, each quantised to 0..L, in one unsigned normalised value.
#if NPR_ENCODING == 2
    const float levels = 63.0;
    const float scale = 255.0;
#else
    const float levels = 16383.0;
    const float scale = 65535.0;
#endif
    float nprDepthUnit = clamp((nprDepth - nprDepthRange.x) / (nprDepthRange.y - nprDepthRange.x), 0.0, 1.0);
    float nprPacked = 1.0 + floor(nprDepthUnit * levels + 0.5);
#if NPR_WRITE_NORMALS
    vec3 nprNormalUnit = floor((nprNormal * 0.5 + 0.5) * levels + 0.5);
    nprPacked += nprNormalUnit.x + nprNormalUnit.y + nprNormalUnit.z;
#endif
    nprGeometry = vec4(nprPacked / scale, 0.0, 0.0, 1.0);
#endif
    gl_FragData[1] = nprGeometry;
#if NPR_REMAPPED_DEPTH
    // Log depth: the same relative precision at every distance (vtkNPRGBufferPass).
    gl_FragDepth = clamp(log(max(nprDepth, 1e-30) / nprDepthRemap.x) / nprDepthRemap.y, 0.0, 1.0);
#endif
  }
