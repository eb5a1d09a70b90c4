/// @ref core

namespace glm
{

}//namespace glm
