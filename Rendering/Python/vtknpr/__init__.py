"""vtknpr: non-photorealistic rendering for VTK (Python wrappers of NPR::RenderingNPR)."""
from .vtkRenderingNPR import *  # noqa: F401,F403
