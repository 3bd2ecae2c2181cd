# early_ack: the CPU side acks a request as soon as no access is in flight,
# without waiting for its own RAM access.
# Must fail ack_match (formal/wb_cdc/wb_cdc.sby neg_early_ack).
s/wire s_ack_d  = s_req \& wait_q \& ~s_busy;/wire s_ack_d  = s_req \& ~s_busy \& ~s_ack_q;/
