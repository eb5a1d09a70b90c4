/// @ref gtc_precision

namespace glm
{

}
