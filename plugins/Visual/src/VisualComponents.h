// SPDX-License-Identifier: MIT
// Visual-only components: Data declarations that a viewer would read; nothing runs in batch.
#pragma once

#include "core/Types.h"
#include "simulation/VisualModel.h"

namespace stroma {

class VisualStyle final : public VisualModel {
 public:
  Data<std::string> d_displayFlags{this, "displayFlags", "showVisual",
                                   "What a viewer shows (SOFA's words: showVisualModels, "
                                   "showBehaviorModels, showForceFields, showWireFrame, ...)."};
};

class BackgroundSetting final : public VisualModel {
 public:
  Data<std::string> d_color{this, "color", "", "Background color 'r g b a'."};
  Data<FileName> d_image{this, "image", {}, "Background image file.", {.mustExist = false}};
};

class VisualGrid final : public VisualModel {
 public:
  Data<double> d_size{this, "size", 10.0, "Grid size.", {.unit = "m"}};
  Data<int> d_nbSubdiv{this, "nbSubdiv", 16, "Subdivisions."};
  Data<std::string> d_plane{this, "plane", "z", "Plane: x, y or z."};
  Data<std::string> d_color{this, "color", "", "Line color."};
  Data<double> d_thickness{this, "thickness", 1.0, "Line thickness (pixels)."};
};

class LineAxis final : public VisualModel {
 public:
  Data<double> d_size{this, "size", 10.0, "Axis length.", {.unit = "m"}};
  Data<std::string> d_axis{this, "axis", "xyz", "Axes drawn."};
  Data<double> d_thickness{this, "thickness", 1.0, "Line thickness (pixels)."};
};

class OglSceneFrame final : public VisualModel {
 public:
  Data<std::string> d_style{this, "style", "Cylinders", "Frame style."};
  Data<std::string> d_alignment{this, "alignment", "BottomRight", "Frame position on screen."};
  Data<bool> d_draw{this, "draw", true, "Draw the frame."};
};

class OglLabel final : public VisualModel {
 public:
  Data<std::string> d_label{this, "label", "", "Text drawn on screen."};
  Data<std::string> d_prefix{this, "prefix", "", "Text drawn before the label."};
  Data<std::string> d_suffix{this, "suffix", "", "Text drawn after the label."};
  Data<std::string> d_color{this, "color", "", "Color: a name ('red') or 'r g b a'."};
  Data<bool> d_selectContrastingColor{this, "selectContrastingColor", false,
                                      "Pick a color that contrasts with the background."};
  Data<int> d_fontsize{this, "fontsize", 14, "Font size (pixels).", {.min = 1.0}};
  Data<int> d_x{this, "x", 10, "Horizontal position on screen (pixels)."};
  Data<int> d_y{this, "y", 10, "Vertical position on screen (pixels)."};
  Data<int> d_updateLabelEveryNbSteps{this, "updateLabelEveryNbSteps", 0,
                                      "Steps between two updates of the label.", {.min = 0.0}};
};

class InteractiveCamera final : public VisualModel {
 public:
  Data<Vec3d> d_position{this, "position", Vec3d(0, 0, 1), "Camera position.", {.unit = "m"}};
  Data<Quat> d_orientation{this, "orientation", Quat::Identity(), "Camera orientation (x y z w)."};
  Data<Vec3d> d_lookAt{this, "lookAt", Vec3d::Zero(), "Point looked at.", {.unit = "m"}};
  Data<double> d_distance{this, "distance", 1.0, "Distance to the point looked at.", {.unit = "m"}};
  Data<double> d_fieldOfView{this, "fieldOfView", 45.0, "Field of view.", {.unit = "deg"}};
  Data<double> d_zNear{this, "zNear", 0.01, "Near clipping distance."};
  Data<double> d_zFar{this, "zFar", 100.0, "Far clipping distance."};
  Data<Vec3d> d_minBBox{this, "minBBox", Vec3d::Zero(), "Lower corner of the viewed box."};
  Data<Vec3d> d_maxBBox{this, "maxBBox", Vec3d::Ones(), "Upper corner of the viewed box."};
  Data<int> d_widthViewport{this, "widthViewport", 800, "Viewport width (pixels)."};
  Data<int> d_heightViewport{this, "heightViewport", 600, "Viewport height (pixels)."};
  Data<double> d_zoomSpeed{this, "zoomSpeed", 250.0, "Zoom speed."};
  Data<double> d_panSpeed{this, "panSpeed", 0.1, "Pan speed."};
  Data<int> d_pivot{this, "pivot", 0, "Rotation pivot."};
  Data<bool> d_fixedLookAt{this, "fixedLookAt", false, "Keep the look-at point fixed."};
  Data<std::string> d_projectionType{this, "projectionType", "Perspective",
                                     "Perspective or Orthographic."};
  Data<bool> d_activated{this, "activated", true, "Whether this camera is the one used."};
};

class LightManager final : public VisualModel {
 public:
  Data<bool> d_shadows{this, "shadows", false, "Shadows."};
  Data<bool> d_softShadows{this, "softShadows", false, "Soft shadows."};
  Data<std::string> d_ambient{this, "ambient", "", "Ambient color 'r g b a'."};
};

/// SpotLight, DirectionalLight and PositionalLight share their Data; the class name says which.
class Light final : public VisualModel {
 public:
  Data<std::string> d_color{this, "color", "", "Light color 'r g b'."};
  Data<Vec3d> d_position{this, "position", Vec3d::Zero(), "Position.", {.unit = "m"}};
  Data<Vec3d> d_direction{this, "direction", Vec3d(0, 0, -1), "Direction."};
  Data<double> d_cutoff{this, "cutoff", 30.0, "Spot cut-off angle.", {.unit = "deg"}};
  Data<double> d_exponent{this, "exponent", 20.0, "Spot exponent."};
  Data<double> d_attenuation{this, "attenuation", 0.0, "Attenuation."};
  Data<bool> d_drawSource{this, "drawSource", false, "Draw the light source."};
  Data<int> d_shadowTextureSize{this, "shadowTextureSize", 0, "Shadow map size (pixels)."};
  Data<double> d_shadowFactor{this, "shadowFactor", 1.0, "Shadow darkness."};
};

class DefaultVisualManagerLoop final : public VisualModel {};

}  // namespace stroma
