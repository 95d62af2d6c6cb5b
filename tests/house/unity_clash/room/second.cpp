// Fixture of tools/check_unity_names: is_on and stop again with the same parameter types (clashes,
// whatever the parameters' names), scaled with others (an overload: allowed), the same alias
// (allowed), a using-directive at namespace scope, and braces inside a literal that must not count.
namespace fixture {
using namespace std;
namespace {

const char* kText = "{ not a brace {";
using Clock = long;
bool is_on(int value) { return value == 2; }
double scaled(double x) { return 2.0 * x; }
[[noreturn]] void stop(const char *reason) { throw reason; }

}  // namespace
}  // namespace fixture
