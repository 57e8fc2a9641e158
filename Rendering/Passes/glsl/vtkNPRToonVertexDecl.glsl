// vtkNPRToonPass, per-vertex lighting: vertex shader declarations (after vtkNPRToonLighting).
out vec2 nprToonIntensityVSOutput; // front and back face
