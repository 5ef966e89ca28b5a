#pragma once
// A markdown table printed with aligned columns, and the number formats the tables use.
#include <cstdint>
#include <string>
#include <vector>

namespace bench {

class MarkdownTable {
 public:
  // A header starting with '>' is right-aligned (numbers); the '>' is not printed.
  explicit MarkdownTable(std::vector<std::string> headers);
  void addRow(std::vector<std::string> cells);
  std::string str() const;

 private:
  std::vector<std::string> headers_;
  std::vector<bool> right_;
  std::vector<std::vector<std::string>> rows_;
};

std::string fixed(double value, int decimals);
std::string milliseconds(double seconds);  // "123.4"
std::string count(std::uint64_t value);    // "1,234,567"
std::string millionsPerSecond(std::uint64_t items, double seconds);
std::string ratio(double numerator, double denominator);  // "0.42x", or "-" when undefined

}  // namespace bench
