// Placeholder header; the dynamic model is built from a Design.
#pragma once
