/// @ref gtx_raw_data

