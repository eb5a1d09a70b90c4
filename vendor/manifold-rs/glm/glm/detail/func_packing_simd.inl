namespace glm{
namespace detail
{

}//namespace detail
}//namespace glm
