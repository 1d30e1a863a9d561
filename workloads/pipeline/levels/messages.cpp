#include "workloads/pipeline/levels/messages.hpp"

#include <stdexcept>
#include <string>

namespace workloads::levels {

namespace {
std::vector<t800sim::INT> words(std::initializer_list<std::uint32_t> values) {
  std::vector<t800sim::INT> out;
  for (std::uint32_t v : values) out.push_back(t800sim::INT(v));
  return out;
}
template <class Number>
void append(std::vector<t800sim::INT>& out, const std::vector<Number>& values) {
  for (Number v : values) out.push_back(t800sim::INT(v));
}
std::uint32_t header_of(std::int32_t word) {
  return std::uint32_t(word);
}
}  // namespace

template <class T>
auto Messages<T>::system_of(const SystemValue& v) -> std::optional<elimination::LinearSystem<C>> {
  if (v.index() == 0) return std::nullopt;
  const std::vector<T>& values = std::get<1>(v);
  // n(n + 1) values: n is the root of n^2 + n - size = 0.
  std::size_t n = 0;
  while ((n + 1) * (n + 2) <= values.size()) ++n;
  if (n * (n + 1) != values.size())
    throw std::logic_error("elimination pipeline: a system of " + std::to_string(values.size()) +
                           " REALs is no n(n + 1)");
  elimination::LinearSystem<C> s;
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = values.begin() + std::ptrdiff_t(i * (n + 1));
    s.a.emplace_back(row, row + std::ptrdiff_t(n));
    s.b.emplace_back(row[std::ptrdiff_t(n)]);
  }
  return s;
}

template <class T>
auto Messages<T>::to_checked(const CheckedPivot& pivot, bool growth_check) -> CheckedValue {
  if (pivot.stop) return {header::kStop, {}, {}};
  Row values = pivot.row;
  if (pivot.step == 0 && growth_check) values.push_back(pivot.scale);
  const std::uint32_t h = checked_header::kPivotRow | std::uint32_t(pivot.step) |
                          (pivot.forward ? checked_header::kForward : 0u);
  return {std::int32_t(h), std::get<1>(packet(0, values)), words({pivot.checksum})};
}

template <class T>
auto Messages<T>::to_checked(const CheckedRow& row) -> CheckedValue {
  return {std::int32_t(row.header()), std::get<1>(packet(0, row.values)), words({row.checksum})};
}

template <class T>
auto Messages<T>::to_checked(const ReturnedRow& row) -> CheckedValue {
  PacketValue p = to_packet(row);
  return {std::get<0>(p), std::move(std::get<1>(p)), {}};
}

template <class T>
auto Messages<T>::to_checked(const Resend& request) -> CheckedValue {
  const std::uint32_t h = checked_header::kResend | std::uint32_t(request.rows.size()) |
                          std::uint32_t(request.lost.size()) << 8 |
                          std::uint32_t(request.avoid.size()) << 16;
  std::vector<t800sim::INT> lists;
  append(lists, request.rows);
  append(lists, request.lost);
  append(lists, request.avoid);
  return {std::int32_t(h), {}, std::move(lists)};
}

template <class T>
bool Messages<T>::is_pivot(const CheckedValue& v) {
  return header_of(std::get<0>(v)) & (checked_header::kPivotRow | std::uint32_t(header::kStop));
}

template <class T>
bool Messages<T>::is_resend(const CheckedValue& v) {
  return header_of(std::get<0>(v)) & checked_header::kResend;
}

template <class T>
auto Messages<T>::checked_pivot_of(const CheckedValue& v, bool growth_check) -> CheckedPivot {
  const std::uint32_t h = header_of(std::get<0>(v));
  CheckedPivot pivot;
  if (h & std::uint32_t(header::kStop)) {
    pivot.stop = true;
    return pivot;
  }
  pivot.step = int(h & checked_header::kNumber);
  pivot.forward = h & checked_header::kForward;
  pivot.row = Row(std::get<1>(v).begin(), std::get<1>(v).end());
  if (pivot.step == 0 && growth_check && !pivot.row.empty()) {
    pivot.scale = pivot.row.back();
    pivot.row.pop_back();
  }
  if (!std::get<2>(v).empty()) pivot.checksum = std::uint32_t(std::get<2>(v).front());
  return pivot;
}

template <class T>
auto Messages<T>::checked_row_of(const CheckedValue& v) -> CheckedRow {
  const std::uint32_t h = header_of(std::get<0>(v));
  CheckedRow row;
  row.step = int((h & checked_header::kNumber) / 256);
  row.index = (h & checked_header::kNumber) % 256;
  row.bad = h & checked_header::kDamaged;
  row.values = Row(std::get<1>(v).begin(), std::get<1>(v).end());
  if (!std::get<2>(v).empty()) row.checksum = std::uint32_t(std::get<2>(v).front());
  return row;
}

template <class T>
auto Messages<T>::returned_row_of(const CheckedValue& v) -> ReturnedRow {
  return returned_row_of(PacketValue{std::get<0>(v), std::get<1>(v)});
}

template <class T>
auto Messages<T>::resend_of(const CheckedValue& v) -> Resend {
  const std::uint32_t h = header_of(std::get<0>(v));
  const std::vector<t800sim::INT>& lists = std::get<2>(v);
  const std::size_t rows = h & 0xff, lost = (h >> 8) & 0xff, avoid = (h >> 16) & 0xff;
  Resend request;
  if (rows + lost + avoid != lists.size()) return request;  // a damaged request: nothing to resend
  for (std::size_t i = 0; i < rows; ++i) request.rows.push_back(std::size_t(lists[i]));
  for (std::size_t i = 0; i < lost; ++i) request.lost.push_back(lists[rows + i]);
  for (std::size_t i = 0; i < avoid; ++i) request.avoid.push_back(lists[rows + lost + i]);
  return request;
}

template struct Messages<float>;
template struct Messages<double>;

}  // namespace workloads::levels
