/// @ref gtx_std_based_type

namespace glm
{

}
