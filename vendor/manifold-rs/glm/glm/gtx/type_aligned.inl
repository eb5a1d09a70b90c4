/// @ref gtc_type_aligned

namespace glm
{

}
