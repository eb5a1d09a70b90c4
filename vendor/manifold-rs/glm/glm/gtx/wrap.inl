/// @ref gtx_wrap

namespace glm
{

}//namespace glm
