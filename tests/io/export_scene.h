// The scene the export tests write: a box baked in place (object 17 of building 3), a glass
// pane (object 18) and a cone placed three times, so kept as a prototype (objects 20 to 22).
#pragma once

#include <string>

namespace veduta::test {

// `head` comes before the materials (a camera, a sun); `brickMaps` are further attributes of
// the brick material (its maps).
inline std::string exportSceneXml(const std::string &head = "", const std::string &brickMaps = "") {
    return "<scene>\n" + head +
        R"(  <material name="brick" diffuse="0.6 0.25 0.2" specular_intensity="0.5" shininess="16" )" + brickMaps +
        R"(/>
  <material name="slate" diffuse="0.2 0.22 0.3"/>
  <material name="pane" glass="true" ior="1.52" tint="0.9 0.95 0.9"/>
  <box size="4 4 3" material="brick" id="17" building="3"/>
  <plane size="2 2" material="pane" translate="0 -2.01 1.5" rotate="90 0 0" id="18"/>
  <prototype name="spire"><cone radius="0.5" height="2" segments="6"/></prototype>
  <instance prototype="spire" material="slate" translate="10 0 0" id="20"/>
  <instance prototype="spire" material="slate" translate="0 10 0" id="21"/>
  <instance prototype="spire" material="slate" translate="0 0 10" rotate="0 0 45" id="22"/>
</scene>)";
}

}  // namespace veduta::test
