#include "fba/arith_encoder.hpp"

namespace fapc::fba {

void ArithEncoder::flush() {
  ++pending_;
  emit(low_ < kCoderQ1 ? 0 : 1);
  low_ = 0;
  high_ = kCoderTop;
  pending_ = 0;
  zero_run_ = 0;
}

}  // namespace fapc::fba
