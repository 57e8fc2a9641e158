  // vtkNPRGBufferPass: geometry attachment = (view depth, packed normal, object id, 1).
  {
#if NPR_HAVE_VERTEX_VC
    float nprDepth = -vertexVCVSOutput.z / vertexVCVSOutput.w;
#else
    float nprDepth = -nprFragmentPositionVC().z;
#endif
    vec4 nprGeometry = vec4(max(nprDepth, 1e-30), 0.0, 0.0, 1.0);
#if NPR_WRITE_NORMALS
#if NPR_HAVE_MAPPER_NORMAL
    vec3 nprNormal = normalVCVSOutput;
#else
    vec3 nprNormal = vec3(0.0);
#endif
    // Unlit actors, lines, points and zero-length or NaN normals: the face normal from the
    // derivatives of the view-space position, turned towards the viewer.
    if (!(dot(nprNormal, nprNormal) > 1e-12))
    {
      vec3 p = nprFragmentPositionVC();
      nprNormal = cross(dFdx(p), dFdy(p));
      nprNormal = dot(nprNormal, nprNormal) > 1e-30 ? nprNormal * sign(dot(nprNormal, -p) + 1e-30)
                                                      : vec3(0.0, 0.0, 1.0);
    }
    nprGeometry.y = nprPackNormal(normalize(nprNormal));
#endif
#if NPR_WRITE_OBJECT_IDS
    nprGeometry.z = nprObjectId;
#endif
    gl_FragData[1] = nprGeometry;
  }
