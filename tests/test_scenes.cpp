#include "test_scenes.h"

namespace veduta::test {

RenderScene sceneFromXml(const std::string &xml) {
    return buildRenderScene(readSceneText(xml, "test.xml", VEDUTA_TEST_DATA));
}

}  // namespace veduta::test
