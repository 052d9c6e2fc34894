#pragma once
// Forwards to the header's home in report/: export_command.cpp, being changed on another branch,
// still includes it by its old name. Delete this file once that include reads
// "report/deployment_report.hpp".
#include "report/deployment_report.hpp"
