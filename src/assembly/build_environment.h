// Turning the scene's <environment> into the Environment the renderer sees: reading cubemap
// faces, crosses or lat-long images through the image library, or baking the clear sky for
// the sun's position.
#pragma once

#include "description/scene_description.h"
#include "scene/environment.h"

namespace veduta {

// `sun` must already stand where the scene puts it: the sky is computed for it. Throws
// InputError at the environment's attribute for unreadable or inconsistent images.
Environment buildEnvironment(const EnvironmentDesc &desc, const Sun &sun);

}  // namespace veduta
