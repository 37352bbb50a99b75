// Warnings that would repeat for every occurrence (an unsupported element, an ignored attribute)
// are given once per name, at the first occurrence, with the count of the others.
#pragma once

#include <map>
#include <string>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::xmt {

class OncePerName {
 public:
  // The first call for `key` keeps `warning`; later calls only count.
  void report(const std::string& key, Diagnostic warning);
  // The kept warnings in order of first occurrence, "(N times; first here)" added where N > 1.
  Diagnostics take();

 private:
  struct Entry {
    std::size_t order;
    Diagnostic warning;
    int count;
  };
  std::map<std::string, Entry> entries_;
};

}  // namespace fapc::xmt
