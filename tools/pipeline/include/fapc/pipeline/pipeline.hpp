// fapc::pipeline, all of it: the reader and writer tables, convert, verify, info, validate, batch, plots, JSON output.
#pragma once

#include "fapc/pipeline/batch.hpp"
#include "fapc/pipeline/combine.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/info.hpp"
#include "fapc/pipeline/json_output.hpp"
#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"
#include "fapc/pipeline/plot.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/pipeline/validate.hpp"
#include "fapc/pipeline/verify.hpp"
