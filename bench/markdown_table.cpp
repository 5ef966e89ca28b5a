#include "markdown_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bench {

MarkdownTable::MarkdownTable(std::vector<std::string> headers) {
  for (std::string& h : headers) {
    const bool right = !h.empty() && h[0] == '>';
    right_.push_back(right);
    headers_.push_back(right ? h.substr(1) : h);
  }
}

void MarkdownTable::addRow(std::vector<std::string> cells) {
  cells.resize(headers_.size());
  rows_.push_back(std::move(cells));
}

std::string MarkdownTable::str() const {
  std::vector<std::size_t> width(headers_.size(), 3);
  for (std::size_t c = 0; c < headers_.size(); ++c) {
    width[c] = std::max(width[c], headers_[c].size());
    for (const auto& row : rows_) width[c] = std::max(width[c], row[c].size());
  }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string out = "|";
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string pad(width[c] - cells[c].size(), ' ');
      out += " " + (right_[c] ? pad + cells[c] : cells[c] + pad) + " |";
    }
    return out + "\n";
  };
  std::string out = line(headers_) + "|";
  for (std::size_t c = 0; c < headers_.size(); ++c) {
    out += right_[c] ? std::string(width[c] + 1, '-') + ":|" : std::string(width[c] + 2, '-') + "|";
  }
  out += "\n";
  for (const auto& row : rows_) out += line(row);
  return out;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string milliseconds(double seconds) {
  const double ms = 1e3 * seconds;
  return fixed(ms, ms < 10 ? 2 : ms < 100 ? 1 : 0);
}

std::string count(std::uint64_t value) {
  std::string digits = std::to_string(value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string millionsPerSecond(std::uint64_t items, double seconds) {
  if (seconds <= 0) return "-";
  return fixed(1e-6 * static_cast<double>(items) / seconds, 2);
}

std::string ratio(double numerator, double denominator) {
  if (!(denominator > 0) || !std::isfinite(numerator)) return "-";
  return fixed(numerator / denominator, 2) + "x";
}

}  // namespace bench
