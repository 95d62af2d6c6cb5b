// Fixture of tools/check_unity_names: private names a second file of the folder repeats.
namespace fixture {
namespace {

using Clock = long;
bool is_on(int command) { return command > 1; }
int scaled(int x) { return 2 * x; }
[[noreturn]] void stop(const char* why) { throw why; }

}  // namespace
}  // namespace fixture
