// The bad-input corpus (Tests/BadInput/cases.txt): every case must end with
// exit code 2 and one clear error line that names what is wrong and where,
// without a crash and without leaving an output folder behind. Each runs
// under a time and a memory limit (kSecondsPerCase, kMegabytesPerCase), so
// a case that hangs or allocates without end fails here, not the machine.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "SoakProcess.h"

using namespace soak::test;

namespace {

struct BadInput {
  std::string file, args, expected, where;
};

void PrintTo(const BadInput& c, std::ostream* os) { *os << c.file << " " << c.args; }

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

constexpr int kSecondsPerCase = 60, kMegabytesPerCase = 4096;

bool hasOption(const std::string& args, const std::string& option) { return args.find(option) != std::string::npos; }

std::vector<BadInput> readCorpus() {
  std::ifstream in(std::string(SOAK_SOURCE_DIR) + "/Tests/BadInput/cases.txt");
  std::vector<BadInput> cases;
  for (std::string line; std::getline(in, line);) {
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> fields;
    std::istringstream s(line);
    for (std::string f; std::getline(s, f, '|');) fields.push_back(trim(f));
    fields.resize(4);
    cases.push_back({fields[0], fields[1], fields[2], fields[3]});
  }
  return cases;
}

class BadInputCorpus : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputCorpus, ExitsWithCode2AndOneClearMessageAndWritesNothing) {
  const BadInput& c = GetParam();
  const std::string scene = std::string(SOAK_SOURCE_DIR) + "/Tests/BadInput/" + c.file;
  ASSERT_TRUE(pathExists(scene)) << scene;
  const std::string out = freshTempPath("bad_" + c.file);
  const bool ownOutput = c.args.find("-o ") != std::string::npos;
  const SoakResult r = runSoakLimited(
      "run " + scene + " " + c.args + (ownOutput ? "" : " -o " + out) + " --device cpu --quiet" +
          (hasOption(c.args, "--frames") || hasOption(c.args, "--time") ? "" : " --frames 1"),
      kSecondsPerCase, kMegabytesPerCase);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("soak: error: ", 0), 0u) << "not an input error: " << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "more than one line: " << r.output;
  EXPECT_NE(r.output.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << r.output;
  if (!c.where.empty()) EXPECT_NE(r.output.find(c.where), std::string::npos) << "expected '" << c.where << "' in: " << r.output;
  EXPECT_FALSE(pathExists(out)) << "an output folder was left for a bad input";
}

// The file's stem, and the options where several cases share a file.
std::string caseName(const ::testing::TestParamInfo<BadInput>& info) {
  std::string n = info.param.file.substr(0, info.param.file.find('.'));
  if (!info.param.args.empty()) n += "_" + info.param.args;
  std::string name;
  for (char ch : n) {
    const char c = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    if (c != '_' || name.empty() || name.back() != '_') name += c;
  }
  name = name.substr(0, 80);  // a case with a long value still gets a readable name
  while (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

INSTANTIATE_TEST_SUITE_P(Tests, BadInputCorpus, ::testing::ValuesIn(readCorpus()), caseName);

TEST(BadInputCorpusSize, HoldsAtLeastNinetyCases) { EXPECT_GE(readCorpus().size(), 90u); }

}  // namespace
