// Parameters that belong to one integrator (a path tracer's strategy, a shift mapping, the
// reconstruction of a gradient render), by name as the command line gives them. Each integrator
// reads the ones it knows; the registry lists which those are, so that the others can be named
// as not applying.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace gdr {

class IntegratorParams {
 public:
  IntegratorParams() = default;
  explicit IntegratorParams(std::map<std::string, std::string> values) : values_(std::move(values)) {}

  void set(const std::string& name, const std::string& value) { values_[name] = value; }
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  const std::map<std::string, std::string>& values() const { return values_; }

  // The value, or `fallback` when it is not given. Throw Error naming the parameter when the
  // value is not one of `choices`, not a finite number >= 0, or not true/false.
  std::string choice(const std::string& name, const std::string& fallback,
                     const std::vector<std::string>& choices) const;
  float non_negative(const std::string& name, float fallback) const;
  bool flag(const std::string& name, bool fallback) const;

 private:
  std::map<std::string, std::string> values_;
};

}  // namespace gdr
