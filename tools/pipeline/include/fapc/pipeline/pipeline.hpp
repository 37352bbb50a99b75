// fapc::pipeline, all of it: the reader and writer tables, convert, verify, info, validate, batch, plots, JSON values
// (the JSON documents of the program are built by the kit's fapc/pipeline/json_output.hpp).
#pragma once

#include "fapc/pipeline/batch.hpp"
#include "fapc/pipeline/combine.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/info.hpp"
#include "fapc/pipeline/json_value.hpp"
#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"
#include "fapc/pipeline/plot.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/pipeline/validate.hpp"
#include "fapc/pipeline/verify.hpp"
