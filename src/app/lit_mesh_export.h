// rayrad export: the solved radiosity mesh as a walkthrough model (binary glTF) with the
// light baked into its vertex colours.
#pragma once

#include <app/pipeline.h>
#include <tonemap/display_transform.h>

#include <string>

namespace rayrad::app {

/// The .glb bytes of the run's diffuse surfaces (mirrors and glass have no light of their
/// own to bake and are left out). Each mesh vertex gets the luminance of its surface there,
/// L = L_e + ρ (E_direct + E_indirect) / π in cd/m², with E_direct the mean of the direct
/// illuminance at the corners of the patches around it and E_indirect the vertex's
/// reconstructed indirect light. COLOR_0 is L through `display`'s white balance and tone
/// operator adapted to `adaptation` cd/m² (steadyDisplay; 0: to these luminances), in linear
/// display RGB in [0, 1] as glTF requires; the attribute _LUMINANCE keeps L's luminance
/// Y in cd/m², and the scene's extras say how the colours were made.
std::string exportLitMesh(const PipelineRun& run, const tonemap::DisplayOptions& display, double adaptation,
                          const std::string& sceneFile);

}  // namespace rayrad::app
