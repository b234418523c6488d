// Replays a libFuzzer target's committed inputs without libFuzzer (any
// compiler): the files given and those of the folders given (README.md
// excepted; a path that does not exist is skipped), in name order, each once. A finding is a crash,
// a sanitizer report or an abort of the target, as under libFuzzer; ctest's timeout stands for
// libFuzzer's.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv);
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char* argv[])
{
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i)
  {
    if (fs::is_directory(argv[i]))
    {
      for (const auto& entry : fs::directory_iterator(argv[i]))
      {
        if (entry.is_regular_file() && entry.path().filename() != "README.md")
        {
          inputs.push_back(entry.path());
        }
      }
    }
    else if (fs::exists(argv[i]))
    {
      inputs.emplace_back(argv[i]);
    }
  }
  std::sort(inputs.begin(), inputs.end());
  LLVMFuzzerInitialize(&argc, &argv);
  for (const fs::path& input : inputs)
  {
    std::ifstream in(input, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::printf("%s\n", input.string().c_str());
    std::fflush(stdout);
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  std::printf("replayed %zu inputs\n", inputs.size());
  return inputs.empty() ? 1 : 0;
}
