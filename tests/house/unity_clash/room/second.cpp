// Fixture of tools/check_unity_names: is_on again with the same parameters (a clash), scaled with
// others (an overload: allowed), the same alias (allowed), and a using-directive at namespace scope.
namespace fixture {
using namespace std;
namespace {

using Clock = long;
bool is_on(int command) { return command == 2; }
double scaled(double x) { return 2.0 * x; }

}  // namespace
}  // namespace fixture
